// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own worker (wasm/worker.js: createDesia's far end, wasm/host.js), started from the
// playground's folder (createDesia's `workerUrl`, web/worker-client.js). A dedicated worker is
// controlled by the service worker whose scope holds its script's URL: started from here it is
// the playground's (web/sw.js), so offline it and everything it loads come from the snapshot,
// as the page does; wasm/worker.js itself lies outside the development server's /web/ scope.
// No code of its own: importing the package's worker is all it does.

import '../wasm/worker.js';
