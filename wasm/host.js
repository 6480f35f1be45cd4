// SPDX-License-Identifier: GPL-3.0-or-later
// The far end of createDesia's protocol: it sits next to the synchronous core, inside the package
// worker (wasm/worker.js: a module Web Worker in browsers, a worker_threads Worker in node) or in
// the caller's thread ({ worker: false }). It only moves messages: every operation is one call of
// the core (loadDesiaModule's functions), and every answer is plain structured-clone data.
//
// Two modules (docs/architecture.md, "Two WebAssembly modules"): the host loads the light one
// first (voxels, contacts, meshes: about half the bytes) and the full one the first time an
// operation throws code 'kind-not-built' (a plate or frame), then runs that operation again on the
// full module, which answers everything from then on. `modules: 'full'` loads only the full one;
// so does a caller that names only the full module (a `wasmBinary`, or a `wasmUrl` without a
// `lightWasmUrl`). If the light module cannot be loaded, the full one is.
//
// Protocol:
//   in:  { type: 'init', wasmUrl?, wasmBinary?,      load the core (once; later inits are no-ops);
//          lightWasmUrl?, modules? }                 wasmUrl/wasmBinary: the full module's,
//                                                    modules: 'light-first' (default) or 'full'
//        { type: 'run', id, op, args }               op: a key of OPERATIONS, args: its arguments
//   out: { type: 'ready', version, module }          the core is loaded (module: 'light' or 'full')
//        { type: 'module', module: 'full' }          the full module was loaded (before the answer
//                                                    to the operation that needed it)
//        { type: 'progress', id, value }             designers only: ~10 a second, and always the
//                                                    last one before the result
//        { type: 'result', id, value }
//        { type: 'error', id, message, code, fatal } id null: loading failed; fatal: the module
//                                                    trapped, the client must start a fresh host
// The client sends one 'run' at a time (see wasm/client.js); cancelling is terminating the worker,
// since a busy single-threaded WebAssembly worker cannot read a 'cancel' message.
//
// Transfers: voxel labels of returned documents travel as an Int32Array (the client turns them
// back into the plain array the core returns) and exported files as a Uint8Array, both moved, not
// copied.

import { documentedCode } from './core.js';

/** Progress is for eyes, not logs: ten messages a second are plenty. */
export const PROGRESS_INTERVAL_MS = 100;
/** designVoxel's liveSurfaces: a snapshot's surfaces cost the search a few ms, at most four times a second. */
export const LIVE_SURFACES_INTERVAL_MS = 250;

/** The methods of a design session the client may call by name. */
const SESSION_METHODS = new Set(['state', 'childCount', 'preview', 'choose', 'next', 'back', 'check']);

function hostError(message, code) {
  return Object.assign(new Error(message), { code });
}

/**
 * A design's onProgress is called after every search node, thousands of times a second:
 * `report(value)` sends the first value at once, then at most one per interval, and `flush()`
 * sends the last unseen one, so the final numbers always arrive before the result. Shared with
 * the playground's worker (web/worker.js).
 */
export function createProgressThrottle(send, intervalMs = PROGRESS_INTERVAL_MS) {
  let latest = null;
  let unsent = false;
  let lastSentAt = -Infinity;
  // The core attaches a `snapshot` (the deepest node so far) once per new depth; one that arrives
  // between two sent values rides on the next one, so a live view never misses the deepest node
  // and gets at most one snapshot per interval.
  let pendingSnapshot = null;
  const sendLatest = () => {
    send(pendingSnapshot && !latest.snapshot ? { ...latest, snapshot: pendingSnapshot } : latest);
    pendingSnapshot = null;
    unsent = false;
    lastSentAt = performance.now();
  };
  return {
    report(value) {
      latest = value;
      if (value?.snapshot) pendingSnapshot = value.snapshot;
      unsent = true;
      if (performance.now() - lastSentAt >= intervalMs) sendLatest();
    },
    flush() {
      if (unsent) sendLatest();
    },
  };
}

/**
 * A request handler around the core. `loadCore(options)` loads it (loadDesiaModule);
 * `post(message, transfer)` sends to the client; `isCancelled()` (in-process only) lets a design
 * stop at its next node once the client has given up on it.
 */
export function createCoreHost(loadCore, post, { isCancelled = () => false } = {}) {
  /** The core that answers (the light one until a plate or frame needs the full one). */
  let corePromise = null;
  let fullPromise = null;
  let loadOptions = {};
  /** Open design sessions by id; each holds WebAssembly memory until disposed. */
  const sessions = new Map();
  let nextSessionId = 1;

  function withProgress(id, run, live = (value) => value) {
    const progress = createProgressThrottle((value) => {
      const sent = live(value);
      post({ type: 'progress', id, value: sent }, surfaceBuffers(sent?.snapshot?.surfaces ?? null));
    });
    const result = run((value) => {
      progress.report(value);
      // false stops the search (status 'cancelled'); in a worker nobody is left to read the
      // answer when the client gave up: it terminates the worker instead.
      return !isCancelled();
    });
    progress.flush();
    return result;
  }

  function openSession(sessionId) {
    const session = sessions.get(sessionId);
    if (!session) {
      throw hostError('designSession: the session was lost (its worker was restarted) or disposed', 'session-lost');
    }
    return session;
  }

  // Each operation: (core, args, id) -> value. The designers take the client's options without
  // onProgress/signal (they cannot cross a worker boundary) and get progress from here.
  const OPERATIONS = {
    check: (core, [text, options]) => core.check(text, options),
    parseDocument: (core, [text, options]) => core.parseDocument(text, options),
    voxelize: (core, [mesh, options]) => core.voxelize(mesh, options),
    toPuz: (core, [assembly, options]) => core.toPuz(assembly, options),
    exportAssembly: (core, [assembly, options]) => core.exportAssembly(assembly, options),
    partSurfaces: (core, [assembly, options]) => core.partSurfaces(assembly, options),
    cutSheets: (core, [assembly, options]) => core.cutSheets(assembly, options),
    parseFrame: (core, [input, options]) => core.parseFrame(input, options),
    // The client's third argument: { liveSurfaces } (createLiveSurfaces), not an option of the core.
    designVoxel: (core, [shape, options, { liveSurfaces = false } = {}], id) =>
      withProgress(id, (onProgress) => core.designVoxel(shape, { ...options, onProgress }),
        liveSurfaces ? createLiveSurfaces(core, shape, options?.source) : undefined),
    designPlate: (core, [input, options], id) =>
      withProgress(id, (onProgress) => core.designPlate(input, { ...options, onProgress })),
    designFrame: (core, [input, options], id) =>
      withProgress(id, (onProgress) => core.designFrame(input, { ...options, onProgress })),
    'session-open': (core, [shape, options]) => {
      const session = core.designSession(shape, options);
      const sessionId = nextSessionId++;
      sessions.set(sessionId, session);
      return sessionId;
    },
    'session-call': (core, [sessionId, method, args]) => {
      if (!SESSION_METHODS.has(method)) throw hostError(`designSession: no method '${String(method)}'`, 'bad-input');
      return openSession(sessionId)[method](...(Array.isArray(args) ? args : []));
    },
    // "Finish automatically from here": a search, so it reports progress like the designers.
    'session-finish': (core, [sessionId, options], id) =>
      withProgress(id, (onProgress) => openSession(sessionId).finish({ ...options, onProgress })),
    'session-dispose': (core, [sessionId]) => {
      sessions.get(sessionId)?.dispose();
      sessions.delete(sessionId);
      return null;
    },
    exportFormats: (core) => core.exportFormats(),
    version: (core) => core.version(),
  };

  /** The full module, loaded once; from then on it answers every operation. */
  function loadFull() {
    const { wasmUrl, wasmBinary } = loadOptions;
    fullPromise ??= loadCore({ wasmUrl, wasmBinary, module: 'full' }).catch((error) => {
      fullPromise = null;
      corePromise = null;  // the next operation starts again (light first)
      throw error;
    });
    corePromise = fullPromise;
    return fullPromise;
  }

  /**
   * The light module, or the full one when asked, when the caller named only the full one (its
   * wasmUrl without a lightWasmUrl, or its bytes), or when the light one fails to load.
   */
  function loadFirst() {
    const { wasmUrl, wasmBinary, lightWasmUrl, modules = 'light-first' } = loadOptions;
    const onlyFull = wasmBinary !== undefined || (wasmUrl !== undefined && lightWasmUrl === undefined);
    if (modules === 'full' || onlyFull) return loadFull();
    return loadCore({ wasmUrl: lightWasmUrl, module: 'light' }).catch(() => loadFull());
  }

  function loadOnce() {
    corePromise ??= loadFirst().catch((error) => {
      corePromise = null;
      throw error;
    });
    return corePromise;
  }

  async function handleInit({ wasmUrl, wasmBinary, lightWasmUrl, modules }) {
    if (!corePromise) loadOptions = { wasmUrl, wasmBinary, lightWasmUrl, modules };
    try {
      const core = await loadOnce();
      post({ type: 'ready', version: String(core.version()), module: core.module() }, []);
    } catch (error) {
      post({ type: 'error', id: null, ...describeError(error), fatal: true }, []);
    }
  }

  function runOperation(core, op, args, id) {
    if (!Object.hasOwn(OPERATIONS, op)) throw hostError(`unknown operation '${String(op)}'`, 'internal');
    return OPERATIONS[op](core, Array.isArray(args) ? args : [], id);
  }

  async function handleRun({ id, op, args }) {
    let core;
    try {
      core = await loadOnce();
    } catch (error) {
      post({ type: 'error', id, ...describeError(error), fatal: true }, []);
      return;
    }
    try {
      let value;
      try {
        value = runOperation(core, op, args, id);
      } catch (error) {
        // The light module refuses a plate or frame (before any work), or a mesh whose plan needs
        // the off-lattice group search (mesh/group_search_entry.h), with kind-not-built: ask the full one.
        if (error?.code !== 'kind-not-built' || core.module() === 'full') throw error;
        core = await loadFull();
        post({ type: 'module', module: core.module() }, []);
        value = runOperation(core, op, args, id);
      }
      const [packed, transfer] = packForTransfer(value);
      post({ type: 'result', id, value: packed }, transfer);
    } catch (error) {
      post({ type: 'error', id, ...describeError(error) }, []);
    }
  }

  return {
    /** Handles one message from the client. */
    handle(message) {
      if (message?.type === 'init') return handleInit(message);
      if (message?.type === 'run') return handleRun(message);
      post({ type: 'error', id: message?.id ?? null, message: `unknown message type '${String(message?.type)}'`, code: 'internal', fatal: false }, []);
      return undefined;
    },
    /** Frees every open session (in-process hosts; a worker's memory goes with the worker). */
    dispose() {
      for (const session of sessions.values()) session.dispose();
      sessions.clear();
    },
  };
}

/**
 * designVoxel's `liveSurfaces` (live design, issue 28 item 8): a progress value's snapshot (the
 * deepest node, `{ depth, labels }`) also carries `surfaces`, the core's part surfaces of the
 * shape with those labels (parts 1..depth placed, depth + 1 the remainder), made here beside the
 * search so that the caller's thread only draws them. At most every LIVE_SURFACES_INTERVAL_MS; a
 * snapshot that comes sooner is held back and rides on a later value, so the deepest node is
 * never lost. Returns a function from the progress value to the value to send.
 */
export function createLiveSurfaces(core, shape, source = '<input>') {
  let shapeDocument = null;
  let held = null;
  let lastAt = -Infinity;
  return (value) => {
    if (!(value?.snapshot || held)) return value;
    const { snapshot = held, ...rest } = value;
    if (performance.now() - lastAt < LIVE_SURFACES_INTERVAL_MS) {
      held = snapshot;
      return rest;
    }
    held = null;
    lastAt = performance.now();
    shapeDocument ??= typeof shape === 'string' ? core.parseDocument(shape, { source }) : shape;
    const document = { ...shapeDocument, voxel: { ...shapeDocument.voxel, labels: Array.from(snapshot.labels) } };
    const surfaces = core.partSurfaces(document, { source: `${source} (deepest node)` });
    return { ...rest, snapshot: { ...snapshot, surfaces } };
  };
}

/** Human-readable text for anything the core or the loader threw. */
export function errorMessage(error) {
  if (error instanceof Error) return error.message || error.name;
  if (typeof error === 'number') return `internal error: uncaught native exception (${error})`;
  return String(error);
}

/**
 * message, code and fatal of anything the core or the loader threw; code is one of the package's
 * documented codes. Fatal: the instance is not to be trusted any more, because it trapped or
 * aborted (its runtime state is gone) or reported 'internal' (a bug in the core, whose state
 * may be inconsistent). Input errors ('bad-input', 'too-large', 'unsupported') leave it usable.
 * The same rule for the package's host and the playground's worker.
 */
export function describeError(error) {
  const message = errorMessage(error);
  const code = documentedCode(typeof error?.code === 'string' ? error.code : 'internal');
  const fatal = error?.fatal === true || (typeof WebAssembly === 'object' && error instanceof WebAssembly.RuntimeError)
    || code === 'internal' || /^Aborted\(/.test(message);
  return { message, code, fatal };
}

/**
 * The value and its transfer list: the voxel labels of a document (the value itself or its
 * `document` field) become an Int32Array that is moved, not copied; bytes (exported files) and
 * the float arrays of part surfaces are moved as they are. Shared with the playground's worker.
 */
export function packForTransfer(value) {
  if (Array.isArray(value) && value.length > 0 && value.every(isPartSurface)) return [value, surfaceBuffers(value)];
  if (value instanceof Uint8Array) {
    // Move a buffer that holds exactly these bytes (a view into a larger one would ship it all).
    const own = value.byteOffset === 0 && value.byteLength === value.buffer.byteLength ? value : value.slice();
    return [own, [own.buffer]];
  }
  const transfer = [];
  const pack = (document) => {
    const labels = document?.voxel?.labels;
    if (!Array.isArray(labels)) return document;
    const packed = Int32Array.from(labels);
    transfer.push(packed.buffer);
    return { ...document, voxel: { ...document.voxel, labels: packed } };
  };
  if (value?.voxel) return [pack(value), transfer];
  if (value?.document?.voxel) return [{ ...value, document: pack(value.document) }, transfer];
  return [value, transfer];
}

function isPartSurface(item) {
  return item?.positions instanceof Float32Array && item?.normals instanceof Float32Array;
}

/** The buffers of part surfaces (partSurfaces' result) to transfer rather than copy. */
export function surfaceBuffers(surfaces) {
  const buffers = new Set();
  for (const surface of surfaces ?? []) {
    if (!isPartSurface(surface)) continue;
    buffers.add(surface.positions.buffer);
    buffers.add(surface.normals.buffer);
  }
  return [...buffers];
}

/** The packed voxel labels (Int32Array) back as the plain array the core returns (in place). */
export function unpackLabels(value) {
  for (const document of [value, value?.document]) {
    if (document?.voxel?.labels instanceof Int32Array) document.voxel.labels = Array.from(document.voxel.labels);
  }
  return value;
}
