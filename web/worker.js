// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's compute worker: the only place where the WebAssembly core runs, so a long
// check never freezes the page and a crashed module can be thrown away with its worker.
//
// Protocol (plain structured-clone messages):
//   in:  { type: 'init' }
//        { type: 'run', id, op: 'check' | 'parse', text, options }
//   out: { type: 'ready', version }
//        { type: 'result', id, value, elapsedMs }   elapsedMs: time spent in the core
//        { type: 'error', id, message, fatal? }   id is null for a failed init.
// `fatal: true` says the module itself is broken (a WebAssembly trap or abort): the page should
// start a fresh worker instead of sending more work here.

import { loadDesiaModule } from '../wasm/index.js';

const WASM_URL = new URL('../dist/desia_wasm.wasm', import.meta.url).href;

let corePromise = null;

/** Loads the core once; later calls share the same promise (and messages keep their order). */
function loadCore() {
  corePromise ??= loadDesiaModule({ wasmUrl: WASM_URL });
  return corePromise;
}

// Each operation returns `[value, transferList]`.
const OPERATIONS = {
  check: (core, text, options) => [core.check(text, options ?? {}), []],
  parse: (core, text, options) => withTransferableLabels(core.parseDocument(text, options ?? {})),
};

/** Voxel labels become an Int32Array so they can be transferred instead of copied. */
function withTransferableLabels(document) {
  const labels = document?.voxel?.labels;
  if (!Array.isArray(labels)) return [document, []];
  const packed = Int32Array.from(labels);
  return [{ ...document, voxel: { ...document.voxel, labels: packed } }, [packed.buffer]];
}

/** Human-readable text for anything thrown by the core or the loader. */
function messageOf(error) {
  if (error instanceof Error) return error.message || error.name;
  if (typeof error === 'number') return `internal error in the WebAssembly core (code ${error})`;
  return String(error);
}

/**
 * Traps and aborts can leave the Emscripten runtime unusable; input errors (the facade's
 * DesiaError codes 'bad-input', 'too-large', 'unsupported') do not. An 'internal' error is a
 * bug somewhere in the core, so we do not trust the instance after it either.
 */
function isFatal(error) {
  return error?.fatal === true
    || error instanceof WebAssembly.RuntimeError
    || error?.code === 'internal'
    || /^Aborted\(/.test(messageOf(error));
}

async function handleInit() {
  try {
    const core = await loadCore();
    self.postMessage({ type: 'ready', version: String(core.version()) });
  } catch (error) {
    corePromise = null;
    self.postMessage({
      type: 'error',
      id: null,
      message: `could not load the WebAssembly core: ${messageOf(error)}`,
      fatal: true,
    });
  }
}

async function handleRun({ id, op, text, options }) {
  const operation = OPERATIONS[op];
  if (!operation) {
    self.postMessage({ type: 'error', id, message: `unknown operation: ${op}` });
    return;
  }
  let core;
  try {
    core = await loadCore();
  } catch (error) {
    self.postMessage({ type: 'error', id, message: `core not loaded: ${messageOf(error)}`, fatal: true });
    return;
  }
  try {
    const started = performance.now();
    const [value, transfer] = operation(core, String(text ?? ''), options);
    const elapsedMs = performance.now() - started;
    self.postMessage({ type: 'result', id, value, elapsedMs }, transfer);
  } catch (error) {
    const fatal = isFatal(error);
    const message = fatal ? `internal error in the WebAssembly core: ${messageOf(error)}` : messageOf(error);
    self.postMessage({ type: 'error', id, message, fatal });
  }
}

self.addEventListener('message', (event) => {
  const message = event.data;
  if (message?.type === 'init') handleInit();
  else if (message?.type === 'run') handleRun(message);
  else self.postMessage({ type: 'error', id: message?.id ?? null, message: `unknown message type: ${message?.type}` });
});
