// SPDX-License-Identifier: GPL-3.0-or-later
//
// The page's core, on the package's own worker API (issue 28): createDesia (wasm/client.js) runs
// the WebAssembly core in a module Web Worker, queues the calls, reports progress, and answers an
// aborted call by terminating that worker (a busy single-threaded worker cannot read a 'cancel'
// message); the next call starts a fresh one. The playground has no worker or protocol of its
// own: `run(op, ...)` names what a panel wants, and each operation is one or a few package calls
// (the document and the part surfaces the view draws, a session's state with its check, ...).
//
// Operations of run(op, text, options, { onProgress, bytes }), resolving with { value, elapsedMs }
// (elapsedMs: the wall-clock time of the calls):
//   'check'            the check report of `text`                         desia.check
//   'parse'            { document, surfaces } of `text`                    parseDocument, partSurfaces
//   'voxelize'         bytes = the mesh; { text (the shape as JSON), voxels, size }
//   'to-puz'           .puz text of a voxel assembly                       desia.toPuz
//   'document-json'    any assembly as its JSON document text              parseDocument
//   'frame-document'   a frame (JSON, OBJ or .fpuz by options.source) as JSON text: parseFrame
//   'mesh-assembly'    options.meshes (a mesh document): { report, surfaces }  check, partSurfaces
//   'mesh-parts'       options.meshes: how many parts the core reads in it      partSurfaces
//   'export'           file bytes                                          exportAssembly
//   'export-formats'   the core's export-format registry                   exportFormats
//   'cut-sheets'       one text per sheet                                  cutSheets
//   'design'           designVoxel (options.jobs: a portfolio of seeds in as many workers) with
//                      live surfaces; 'design-plate', 'design-frame': designPlate, designFrame;
//                      the result with `surfaces` of its document
//   'session-open' (text, options), 'session-next', 'session-back', 'session-choose' and
//   'session-preview' ({ n }), 'session-children' ({ count }), 'session-finish' ({ timeLimit }),
//   'session-close': one design session at a time; a snapshot is { partsPlaced, targetParts,
//                      complete, childCount, document, steps, message, report, surfaces, moved? }
// A design's progress values carry `snapshot`: voxels { depth, labels, surfaces } (the package's
// liveSurfaces: made in the worker), plates and frames { depth, placed }.

import { createDesia } from '../wasm/index.js';

const WASM_URL = new URL('../dist/desia_wasm.wasm', import.meta.url).href;
/** The light module the worker loads first; the full one (WASM_URL) for the first plate or frame. */
const LIGHT_WASM_URL = new URL('../dist/desia_light.wasm', import.meta.url).href;
/** The package's worker, started from the playground's folder so that web/sw.js controls it (core-worker.js). */
const WORKER_URL = new URL('./core-worker.js', import.meta.url).href;
/** Consecutive failed worker starts before we stop restarting on our own. */
export const MAX_FAILED_STARTS = 3;

/**
 * What the page says when a worker died: `message`, and whether a fresh one was started. The calls
 * that waited for that worker fail with the same words, so whichever the page shows last says it.
 */
function crashText(message, willRestart) {
  return willRestart
    ? `${message}. A fresh worker was started; choose an assembly to try again.`
    : `${message}. The worker failed ${MAX_FAILED_STARTS} times in a row; choosing an assembly tries once more.`;
}

/** The rejection of requests that were cancelled (not a failure: nothing to report). */
export class CancelledError extends Error {
  constructor(message = 'cancelled') {
    super(message);
    this.name = 'CancelledError';
    this.cancelled = true;
  }
}

/** Documents whose parts have surfaces to draw: voxel parts, plates and frames (contact graphs have none). */
function hasSurfaces(document) {
  if (document?.kind === 'voxel') return true;
  if (document?.kind === 'frame') return Array.isArray(document.beams) && document.beams.length > 0;
  return document?.kind === 'plate' && Array.isArray(document.plates) && document.plates.length > 0;
}

/** The source name for a document sent as JSON: a name ending in .fpuz or .obj would be read as that format. */
function jsonSource(source) {
  return String(source ?? '<input>').replace(/\.(fpuz|obj)$/i, '.$1 (as JSON)');
}

function childIndex(options) {
  const n = options?.n;
  if (!Number.isInteger(n)) throw Object.assign(new Error(`child index must be an integer, got ${String(n)}`), { code: 'bad-input' });
  return n;
}

export class CoreWorker {
  /** The package's API (createDesia's result) once started, else null. */
  #desia = null;
  #starting = null;
  #failedStarts = 0;
  #generation = 0;
  /** The calls under way: each has an AbortController that cancel() aborts. */
  #running = new Set();
  /** The open design session (the package's proxy), or null. */
  #session = null;
  #onStart;
  #onReady;
  #onCrash;

  /**
   * `onStart()` when a worker starts (first time, after a crash or a cancel), `onReady(version)`
   * once it has loaded the core, `onCrash(text, willRestart)` when one dies (`text` says what
   * happened and what comes next).
   */
  constructor({ onStart = () => {}, onReady, onCrash }) {
    this.#onStart = onStart;
    this.#onReady = onReady;
    this.#onCrash = onCrash;
  }

  /**
   * Counts worker starts. State kept inside a worker (a design session) lives only as long as
   * the generation it was created in.
   */
  get generation() {
    return this.#generation;
  }

  /** Starts the core (once; later calls share the start). Requests made meanwhile wait for it. */
  start() {
    this.#starting ??= this.#startCore();
    return this.#starting;
  }

  async #startCore() {
    this.#generation += 1;
    this.#onStart();
    try {
      this.#desia ??= await createDesia({ wasmUrl: WASM_URL, lightWasmUrl: LIGHT_WASM_URL, workerUrl: WORKER_URL });
      // A fresh worker: the package starts it with the next call; asking for the export formats
      // (a table) loads the core now, so that the page is ready when the user acts.
      await this.#desia.exportFormats();
      this.#failedStarts = 0;
      this.#onReady(this.#desia.version());
      return this.#desia;
    } catch (error) {
      this.#failedStarts += 1;
      this.#starting = null;
      const willRestart = this.#failedStarts < MAX_FAILED_STARTS;
      const text = crashText(String(error?.message ?? error), willRestart);
      this.#onCrash(text, willRestart);
      // The calls that waited for this start fail with it; a fresh start begins for the next ones.
      if (willRestart) this.start().catch(() => {});
      throw Object.assign(new Error(text), { code: error?.code ?? 'internal' });
    }
  }

  /**
   * Runs `op` (see the top of this file) on `text`; resolves with `{ value, elapsedMs }`.
   * `onProgress(value)` receives the design's progress. `bytes` (a Uint8Array, e.g. a mesh) is
   * copied to the worker, so the caller keeps its own copy for the next request.
   */
  async run(op, text, options = {}, { onProgress, bytes } = {}) {
    const operation = Object.hasOwn(OPERATIONS, op) ? OPERATIONS[op] : null;
    if (!operation) throw Object.assign(new Error(`unknown operation: ${op}`), { code: 'internal' });
    // After repeated failed starts a new request is worth one more try.
    if (!this.#starting) this.#failedStarts = 0;
    // Registered at once: a cancel right after this call (before the core is there) reaches it.
    const controller = new AbortController();
    const call = { signal: controller.signal, onProgress };
    this.#running.add(controller);
    // Session steps take no signal: a cancel answers at once all the same (their worker is
    // terminated by cancel()).
    const aborted = new Promise((resolve, reject) => {
      controller.signal.addEventListener('abort', () => reject(new CancelledError()), { once: true });
    });
    aborted.catch(() => {});
    const started = performance.now();
    try {
      const desia = await Promise.race([this.start(), aborted]);
      const value = await Promise.race([operation(this, desia, String(text ?? ''), options ?? {}, { ...call, bytes }), aborted]);
      return { value, elapsedMs: performance.now() - started };
    } catch (error) {
      if (controller.signal.aborted) throw new CancelledError();
      // The module trapped or aborted: the package has dropped its worker (sessions with it).
      if (error?.fatal) this.#lost(String(error.message));
      throw error;
    } finally {
      this.#running.delete(controller);
    }
  }

  /**
   * Stops whatever the core is doing within a moment: every call rejects with a CancelledError,
   * the package's worker is terminated (its searches and any design session with it) and a
   * fresh core is loaded at once.
   */
  cancel() {
    const running = [...this.#running];
    this.#running.clear();
    for (const controller of running) controller.abort();
    this.#forgetSession();
    const terminated = this.#desia?.terminate() ?? Promise.resolve();
    this.#starting = terminated.then(() => this.#startCore());
    this.#starting.catch(() => {});
  }

  /** A worker died under a call: its session with it; the next call starts a fresh one. */
  #lost(message) {
    this.#forgetSession();
    this.#generation += 1;
    this.#onCrash(crashText(message, true), true);
    this.#onStart();
    this.#desia?.exportFormats().then(() => this.#onReady(this.#desia.version()), () => {});
  }

  #forgetSession() {
    this.#session = null;
  }

  /** The open session, or an error that says there is none. */
  session() {
    if (!this.#session) throw Object.assign(new Error('no design session is open (start one first)'), { code: 'bad-input' });
    return this.#session;
  }

  async openSession(desia, text, options, signal) {
    const previous = this.#session;
    this.#session = null;
    await previous?.dispose().catch(() => {});
    this.#session = await desia.designSession(text, { ...options, signal });
    return this.#session;
  }

  async closeSession() {
    const session = this.#session;
    this.#session = null;
    await session?.dispose();
  }
}

/** `value` (holding a `document`) with `surfaces`: the part surfaces of that document, or null. */
async function withSurfaces(desia, value, source, signal) {
  const surfaces = hasSurfaces(value.document)
    ? await desia.partSurfaces(value.document, { source: jsonSource(source), signal }) : null;
  return { ...value, surfaces };
}

/** The session's current node, with its check report, its children's count and its surfaces. */
async function sessionSnapshot(desia, session, signal, extra = {}) {
  const { partsPlaced, targetParts, complete, document, steps, message } = await session.state();
  // A complete puzzle has no children; asking would only generate an empty list.
  const childCount = complete ? 0 : await session.childCount();
  const report = await session.check();
  return withSurfaces(desia, { ...extra, partsPlaced, targetParts, complete, childCount, document, steps, message, report }, 'design session', signal);
}

/** Each operation: (worker, desia, text, options, { signal, onProgress, bytes }) -> value. */
const OPERATIONS = {
  check: (worker, desia, text, options, { signal }) => desia.check(text, { ...options, signal }),
  parse: async (worker, desia, text, options, { signal }) => {
    const document = await desia.parseDocument(text, { ...options, signal });
    return withSurfaces(desia, { document }, options.source, signal);
  },
  voxelize: async (worker, desia, text, options, { signal, bytes }) => {
    if (!(bytes instanceof Uint8Array)) throw Object.assign(new Error('voxelize: no mesh bytes were sent'), { code: 'bad-input' });
    const document = await desia.voxelize(bytes, { ...options, signal });
    return { text: JSON.stringify(document), voxels: document.parts?.[0]?.voxelCount ?? 0, size: document.voxel?.size ?? [] };
  },
  'to-puz': (worker, desia, text, options, { signal }) => desia.toPuz(text, { ...options, signal }),
  'document-json': async (worker, desia, text, options, { signal }) => JSON.stringify(await desia.parseDocument(text, { ...options, signal })),
  'frame-document': async (worker, desia, text, options, { signal }) => JSON.stringify(await desia.parseFrame(text, { ...options, signal })),
  'mesh-assembly': async (worker, desia, text, { meshes, ...options }, { signal }) => {
    const report = await desia.check(meshes, { ...options, signal });
    return { report, surfaces: await desia.partSurfaces(meshes, { signal }) };
  },
  'mesh-parts': async (worker, desia, text, { meshes }, { signal }) => (await desia.partSurfaces(meshes, { signal })).length,
  export: (worker, desia, text, options, { signal }) => desia.exportAssembly(text, { ...options, signal }),
  'export-formats': (worker, desia, text, options, { signal }) => desia.exportFormats({ signal }),
  'cut-sheets': (worker, desia, text, options, { signal }) => desia.cutSheets(text, { ...options, signal }),
  design: async (worker, desia, text, options, { signal, onProgress }) => {
    const result = await desia.designVoxel(text, { ...options, liveSurfaces: true, signal, onProgress });
    return withSurfaces(desia, result, options.source, signal);
  },
  'design-plate': async (worker, desia, text, options, { signal, onProgress }) =>
    withSurfaces(desia, await desia.designPlate(text, { ...options, signal, onProgress }), options.source, signal),
  'design-frame': async (worker, desia, text, options, { signal, onProgress }) =>
    withSurfaces(desia, await desia.designFrame(text, { ...options, signal, onProgress }), options.source, signal),
  'session-open': async (worker, desia, text, options, { signal }) =>
    sessionSnapshot(desia, await worker.openSession(desia, text, options, signal), signal),
  'session-next': async (worker, desia, text, options, { signal }) => {
    const session = worker.session();
    return sessionSnapshot(desia, session, signal, { moved: await session.next() });
  },
  'session-back': async (worker, desia, text, options, { signal }) => {
    const session = worker.session();
    return sessionSnapshot(desia, session, signal, { moved: await session.back() });
  },
  'session-choose': async (worker, desia, text, options, { signal }) => {
    const session = worker.session();
    await session.choose(childIndex(options));
    return sessionSnapshot(desia, session, signal);
  },
  'session-preview': async (worker, desia, text, options, { signal }) => {
    const index = childIndex(options);
    const document = await worker.session().preview(index);
    // A plate or frame session's child is a step (the plate or beam, its direction, its joints),
    // not an assembly.
    if (document && (typeof document.plate === 'number' || typeof document.beam === 'number')) return { index, step: document };
    const report = await desia.check(JSON.stringify(document), { source: `child ${index}`, signal });
    return withSurfaces(desia, { index, document, report }, `child ${index}`, signal);
  },
  'session-children': async (worker, desia, text, options, { signal }) => {
    const session = worker.session();
    const count = Math.min(await session.childCount(), Number.isInteger(options.count) ? options.count : 0);
    const children = [];
    for (let index = 0; index < count; index += 1) {
      const preview = await session.preview(index);
      if (preview?.kind !== 'voxel') break; // plates and frames: a child is a step, not an assembly
      children.push({ index, surfaces: await desia.partSurfaces(preview, { source: `child ${index}`, signal }) });
    }
    return children;
  },
  'session-finish': async (worker, desia, text, options, { signal, onProgress }) => {
    // The session's own node is on screen (step by step): its live view is the page's to add.
    const withoutSnapshots = onProgress && ((value) => {
      const { snapshot, ...rest } = value;
      onProgress(rest);
    });
    const result = await worker.session().finish({ ...options, signal, onProgress: withoutSnapshots });
    return withSurfaces(desia, result, 'finished design', signal);
  },
  'session-close': async (worker) => {
    await worker.closeSession();
    return null;
  },
};
