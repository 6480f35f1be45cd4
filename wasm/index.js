// SPDX-License-Identifier: GPL-3.0-or-later
// The desia package entry point. `createDesia()` (wasm/client.js) is the promise-based API, the
// same in browsers and node: it runs the core in a worker and talks to it with the protocol of
// wasm/host.js. `loadDesiaModule()` (wasm/core.js) loads the synchronous core in the calling
// thread (inside a worker, or in node scripts). The package owns loading the WebAssembly module,
// so callers need no setup() and no path fiddling. Declarations: wasm/index.d.ts.

export { DesiaError, loadDesiaModule } from './core.js';
export { createDesia } from './client.js';
