// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's compute worker: the only place where the WebAssembly core runs, so a long
// check or design never freezes the page and a crashed (or cancelled) module can be thrown away
// with its worker.
//
// Protocol (plain structured-clone messages):
//   in:  { type: 'init' }
//        { type: 'run', id, op, text, options, bytes? }
//          op 'check' | 'parse'   text = the assembly, options = the core's options; parse's
//                                 result is { document, surfaces }
//          op 'voxelize'          bytes = the mesh (OBJ or STL), options = { resolution, source };
//                                 result { text (the shape's JSON document), voxels, size }
//          op 'to-puz'            text = a voxel assembly; result = its .puz text
//          op 'document-json'     text = any assembly; result = its JSON document as text
//          op 'export'            text = the assembly, options = exportAssembly's { format,
//                                 part, voxelSize, source }; result = bytes (transferred)
//          op 'export-formats'    no text; result = the core's export-format registry
//                                 (exportFormats: [{ name, kinds, options, perSheet, what }])
//          op 'cut-sheets'        text = a plate structure, options = cutSheets' { format, sheet,
//                                 kerf, spacing, hairline, source }; result = one text per sheet
//          op 'design'            text = the voxel shape, options = designVoxel's options (no onProgress)
//          op 'design-plate'      text = the plate design, options = designPlate's { seed,
//                                 candidates, timeLimit, source }; result = the DesignResult
//                                 (document = the joint plan, or null) with `surfaces`
//          op 'design-frame'      text = the frame (JSON, or OBJ / .fpuz text named by
//                                 options.source), options = designFrame's { seed, candidates,
//                                 timeLimit, jointSize, source }; result as for 'design-plate'
//          op 'frame-document'    text = a frame as JSON, OBJ or .fpuz (by options.source);
//                                 result = its JSON document as text (parseFrame)
//          op 'session-open'      text = the voxel shape, plate design or frame, options = designSession's options
//          op 'session-next' | 'session-back' | 'session-close'
//          op 'session-choose' | 'session-preview'   options = { n } (child index)
//          op 'session-children'  options = { count }: the part surfaces of the first `count`
//                                 ranked children (voxel sessions), for thumbnails:
//                                 [{ index, surfaces }]
//          op 'session-finish'    options = { timeLimit }: "finish automatically from here", with
//                                 progress; result as for 'design'; the session does not move
//   out: { type: 'ready', version }
//        { type: 'progress', id, value }         designs only: { nodesVisited, depth, bestDepth,
//                                                targetParts, elapsedSeconds, snapshot? }, at most
//                                                ~10 per second, always including the last one;
//                                                snapshot: the deepest node so far (createLiveView)
//        { type: 'result', id, value, elapsedMs }   elapsedMs: time spent in the core
//        { type: 'error', id, message, fatal?, code? }   id is null for a failed init; code is
//                                                one of the package's error codes (index.d.ts).
// `fatal: true` says the module itself is broken (a WebAssembly trap or abort): the page should
// start a fresh worker instead of sending more work here.
//
// Cancelling: while the core runs, this worker cannot read messages, so there is no 'cancel'
// message; the page terminates the worker and starts a new one (which also ends any session).
//
// Session results are snapshots { partsPlaced, targetParts, complete, childCount, document,
// surfaces, report, moved? } (report = the core's check of the current assembly); a preview is
// { index, document, surfaces, report }; a design result carries `surfaces` too. `surfaces` is
// the core's partSurfaces of `document` (Float32Arrays, transferred; voxel parts, plates or frames) or
// null (no document, or one known only by its contacts). One session per worker: opening one disposes the previous one.

import { loadDesiaModule } from '../wasm/core.js';
// The package host's helpers: progress throttling, label packing and error classification are
// the same for the playground as for createDesia.
import { createProgressThrottle, describeError, errorMessage, packForTransfer, surfaceBuffers } from '../wasm/host.js';

const WASM_URL = new URL('../dist/desia_wasm.wasm', import.meta.url).href;

let corePromise = null;
/** The open design session (a WebAssembly handle: dispose it before dropping it). */
let session = null;

/** Loads the core once; later calls share the same promise (and messages keep their order). */
function loadCore() {
  corePromise ??= loadDesiaModule({ wasmUrl: WASM_URL });
  return corePromise;
}

// Each operation returns `[value, transferList]`.
const OPERATIONS = {
  check: (core, text, options) => [core.check(text, options ?? {}), []],
  parse: (core, text, options) => {
    const document = core.parseDocument(text, options ?? {});
    return withSurfaces(core, { document }, options?.source);
  },
  design: (core, text, options, context) => designOperation(core, 'designVoxel', text, options, context),
  'design-plate': (core, text, options, context) => designOperation(core, 'designPlate', text, options, context),
  'design-frame': (core, text, options, context) => designOperation(core, 'designFrame', text, options, context),
  'frame-document': (core, text, options) => [JSON.stringify(core.parseFrame(text, options ?? {})), []],
  voxelize: (core, text, options, { bytes }) => {
    if (!(bytes instanceof Uint8Array)) throw Object.assign(new Error('voxelize: no mesh bytes were sent'), { code: 'bad-input' });
    const document = core.voxelize(bytes, options ?? {});
    // The page keeps the shape as JSON text (what the design panel and the checks take) and
    // shows its size; stringifying here spares the page a large object copy.
    const value = { text: JSON.stringify(document), voxels: document.parts?.[0]?.voxelCount ?? 0, size: document.voxel?.size ?? [] };
    return [value, []];
  },
  'to-puz': (core, text, options) => [core.toPuz(text, options ?? {}), []],
  'document-json': (core, text, options) => [JSON.stringify(core.parseDocument(text, options ?? {})), []],
  export: (core, text, options) => {
    if (typeof core.exportAssembly !== 'function') {
      throw Object.assign(new Error('this build of the core has no exporter (rebuild: bash scripts/build.sh wasm)'), { code: 'unsupported' });
    }
    return packForTransfer(core.exportAssembly(text, options ?? {}));
  },
  'export-formats': (core) => [core.exportFormats(), []],
  'cut-sheets': (core, text, options) => [core.cutSheets(text, options ?? {}), []],
  'session-open': (core, text, options) => {
    closeSession();
    session = core.designSession(text, options ?? {});
    return sessionSnapshot(core);
  },
  'session-next': (core) => sessionSnapshot(core, { moved: openSession().next() }),
  'session-back': (core) => sessionSnapshot(core, { moved: openSession().back() }),
  'session-choose': (core, text, options) => {
    openSession().choose(childIndex(options));
    return sessionSnapshot(core);
  },
  'session-preview': (core, text, options) => {
    const index = childIndex(options);
    const document = openSession().preview(index);
    // A plate or frame session's child is a step (the plate or beam, its direction, its joints),
    // not an assembly.
    if (document && (typeof document.plate === 'number' || typeof document.beam === 'number')) return [{ index, step: document }, []];
    // The core checks the previewed assembly from its own JSON document.
    const report = core.check(JSON.stringify(document), { source: `child ${index}` });
    return withSurfaces(core, { index, document, report }, `child ${index}`);
  },
  'session-children': (core, text, options) => {
    const current = openSession();
    const count = Math.min(current.childCount(), Number.isInteger(options?.count) ? options.count : 0);
    const children = [];
    for (let index = 0; index < count; index += 1) {
      const preview = current.preview(index);
      if (preview?.kind !== 'voxel') break; // plates and frames: a child is a step, not an assembly
      children.push({ index, surfaces: core.partSurfaces(preview, { source: `child ${index}` }) });
    }
    return [children, children.flatMap(({ surfaces }) => surfaceBuffers(surfaces))];
  },
  'session-finish': (core, text, options, { id }) => {
    // The session's own node is on screen (step by step): its live view is the page's to add.
    const progress = createProgressThrottle((value) => {
      const { snapshot, ...rest } = value;
      self.postMessage({ type: 'progress', id, value: rest });
    });
    const result = openSession().finish({ ...(options ?? {}), onProgress: progress.report });
    progress.flush();
    return withSurfaces(core, result, 'finished design');
  },
  'session-close': () => {
    closeSession();
    return [null, []];
  },
};

/** Runs designVoxel, designPlate or designFrame, posting throttled progress for request `id`. */
function designOperation(core, designer, text, options, { id }) {
  // Returning nothing from onProgress lets the search go on; the page stops it by terminating
  // the worker.
  const live = createLiveView(core, designer === 'designVoxel' ? text : null, options?.source);
  const progress = createProgressThrottle((value) => postProgress(id, live(value)));
  const result = core[designer](text, { ...(options ?? {}), onProgress: progress.report });
  progress.flush();
  return withSurfaces(core, result, options?.source);
}

/** Live design: a snapshot's surfaces are worth a few ms of the search at most four times a second. */
const LIVE_INTERVAL_MS = 250;

/**
 * Live design (issue 11): progress values carry `snapshot` (the deepest node so far) whenever it
 * grew. For a voxel design the worker turns it into `{ depth, document, surfaces }` (the shape's
 * document with the node's labels, and the core's part surfaces of it: parts 1..depth placed,
 * part depth + 1 the remainder), at most every LIVE_INTERVAL_MS; a snapshot held back rides on a
 * later value. Plate and frame snapshots are `{ depth, placed }` (input indices): the page
 * recolours what it already draws, so they pass as they are.
 */
function createLiveView(core, shapeText, source = '<input>') {
  let shape = null;
  let held = null;
  let lastAt = -Infinity;
  return (value) => {
    if (!shapeText || !(value?.snapshot || held)) return value;
    const { snapshot = held, ...rest } = value;
    if (performance.now() - lastAt < LIVE_INTERVAL_MS) {
      held = snapshot;
      return rest;
    }
    held = null;
    lastAt = performance.now();
    shape ??= core.parseDocument(shapeText, { source });
    const document = { ...shape, voxel: { ...shape.voxel, labels: Array.from(snapshot.labels) } };
    const surfaces = core.partSurfaces(document, { source: `${source} (deepest node)` });
    return { ...rest, snapshot: { depth: snapshot.depth, document, surfaces } };
  };
}

function postProgress(id, value) {
  self.postMessage({ type: 'progress', id, value }, surfaceBuffers(value?.snapshot?.surfaces ?? null));
}

function openSession() {
  if (!session) throw Object.assign(new Error('no design session is open (start one first)'), { code: 'bad-input' });
  return session;
}

function closeSession() {
  session?.dispose();
  session = null;
}

function childIndex(options) {
  const n = options?.n;
  if (!Number.isInteger(n)) throw Object.assign(new Error(`child index must be an integer, got ${String(n)}`), { code: 'bad-input' });
  return n;
}

/** The current node of the session, with its check report and the number of its children. */
function sessionSnapshot(core, extra = {}) {
  const current = openSession();
  const { partsPlaced, targetParts, complete, document, steps, message } = current.state();
  // A complete puzzle has no children; asking would only generate an empty list.
  const childCount = complete ? 0 : current.childCount();
  const snapshot = { ...extra, partsPlaced, targetParts, complete, childCount, document, steps, message, report: current.check() };
  return withSurfaces(core, snapshot, 'design session');
}

/** Documents whose parts have surfaces to draw: voxel parts, plates and frames (contact graphs have none). */
function hasSurfaces(document) {
  if (document?.kind === 'voxel') return true;
  if (document?.kind === 'frame') return Array.isArray(document.beams) && document.beams.length > 0;
  return document?.kind === 'plate' && Array.isArray(document.plates) && document.plates.length > 0;
}

/**
 * `value` (holding a `document`) with `surfaces`: the core's part surfaces of that document for
 * the 3D view (null when it is not a voxel, plate or frame document), as `[value, transferList]`: the labels and
 * the surfaces' float arrays are moved to the page, not copied.
 */
function withSurfaces(core, value, source = '<input>') {
  const { document } = value;
  // The document is JSON whatever the file was: a name ending in .fpuz or .obj would make the core
  // read it as that format.
  const name = String(source ?? '<input>').replace(/\.(fpuz|obj)$/i, '.$1 (as JSON)');
  const surfaces = hasSurfaces(document) ? core.partSurfaces(document, { source: name }) : null;
  const [packed, transfer] = packForTransfer({ ...value, surfaces });
  return [packed, [...transfer, ...surfaceBuffers(surfaces)]];
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
      message: `could not load the WebAssembly core: ${errorMessage(error)}`,
      fatal: true,
    });
  }
}

async function handleRun({ id, op, text, options, bytes }) {
  const operation = Object.hasOwn(OPERATIONS, op) ? OPERATIONS[op] : null;
  if (!operation) {
    self.postMessage({ type: 'error', id, message: `unknown operation: ${op}` });
    return;
  }
  let core;
  try {
    core = await loadCore();
  } catch (error) {
    self.postMessage({ type: 'error', id, message: `core not loaded: ${errorMessage(error)}`, fatal: true });
    return;
  }
  try {
    const started = performance.now();
    const [value, transfer] = operation(core, String(text ?? ''), options, { id, bytes });
    const elapsedMs = performance.now() - started;
    self.postMessage({ type: 'result', id, value, elapsedMs }, transfer);
  } catch (error) {
    // Fatal (a trap, an abort or an 'internal' error: the instance is not to be trusted) by the
    // same rule as the package's host; `code` is one of the package's error codes.
    const { message, code, fatal } = describeError(error);
    self.postMessage({ type: 'error', id, message: fatal ? `internal error in the WebAssembly core: ${message}` : message, fatal, code });
  }
}

self.addEventListener('message', (event) => {
  const message = event.data;
  if (message?.type === 'init') handleInit();
  else if (message?.type === 'run') handleRun(message);
  else self.postMessage({ type: 'error', id: message?.id ?? null, message: `unknown message type: ${message?.type}` });
});
