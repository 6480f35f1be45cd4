// SPDX-License-Identifier: GPL-3.0-or-later
// The package worker: createDesia() starts this script as a module Web Worker in browsers and as a
// worker_threads Worker in node, and talks to it with the protocol described in wasm/host.js. It
// loads the synchronous core with loadDesiaModule, so a long check or design never blocks the
// caller's thread and cancelling is terminating this worker.

import { loadDesiaModule } from './core.js';
import { createCoreHost } from './host.js';

const inNode = typeof process === 'object' && typeof process.versions?.node === 'string'
  && typeof importScripts === 'undefined';

if (inNode) {
  // node buffers messages on parentPort until a listener is attached, so nothing is lost while
  // this import resolves; awaiting it here means the listener is there once this module is.
  const { parentPort } = await import('node:worker_threads');
  const host = createCoreHost(loadDesiaModule, (message, transfer) => parentPort.postMessage(message, transfer));
  parentPort.on('message', (message) => host.handle(message));
} else {
  // Listen synchronously: a module worker's messages are dispatched once the script has run.
  const host = createCoreHost(loadDesiaModule, (message, transfer) => self.postMessage(message, transfer));
  self.addEventListener('message', (event) => host.handle(event.data));
}
