// SPDX-License-Identifier: GPL-3.0-or-later
// The synchronous side of the desia package: `loadDesiaModule()` loads the WebAssembly module in
// the calling thread (inside a worker, or in node scripts) and returns the core's functions with
// their arguments checked for type, so that a mistake gives a DesiaError that names the function
// and the value instead of a silent default. Ranges and meanings are the core's to check: its
// messages name the value and the accepted range. All analysis happens in the C++ core.

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string' &&
  typeof window === 'undefined' && typeof importScripts === 'undefined';

/** The error codes of the package (index.d.ts ErrorCode); anything else is reported as 'internal'. */
export const ERROR_CODES = Object.freeze(['bad-input', 'too-large', 'unsupported', 'internal', 'terminated', 'session-lost', 'kind-not-built']);

/**
 * The two WebAssembly modules built from the same core (docs/architecture.md): 'full' has every
 * kind; 'light' has voxels, contacts and meshes and throws code 'kind-not-built' for a plate or
 * frame, upon which createDesia's worker loads the full module and asks it again (wasm/host.js).
 */
export const MODULES = Object.freeze(['light', 'full']);
/** The calls only the full module binds (wasm/bindings_plate_frame.cpp). */
const FULL_ONLY = Object.freeze({ designPlate: 'plate', designFrame: 'frame', parseFrame: 'frame', cutSheets: 'plate' });

/** `code` when it is one of ERROR_CODES, else 'internal' (e.g. node's 'ENOENT'). */
export function documentedCode(code) {
  return ERROR_CODES.includes(code) ? code : 'internal';
}

/**
 * Error thrown for bad input and failures. `code`: from the core 'bad-input', 'too-large',
 * 'unsupported', 'internal', or 'kind-not-built' (the light module was asked for a plate or a
 * frame; createDesia answers it by loading the full module); from createDesia also 'terminated'
 * (terminate() was called) and 'session-lost' (the worker holding a design session was stopped).
 */
export class DesiaError extends Error {
  constructor(message, code = 'internal', { fatal = false } = {}) {
    super(message);
    this.name = 'DesiaError';
    this.code = documentedCode(code);
    /** True when the WebAssembly instance trapped or the worker died: createDesia replaces it by itself. */
    this.fatal = fatal;
  }
}

function rethrow(error) {
  if (error instanceof DesiaError) throw error;
  if (typeof WebAssembly === 'object' && error instanceof WebAssembly.RuntimeError) {
    throw new DesiaError(`WebAssembly trap: ${error.message}; this module instance cannot be used again`, 'internal', { fatal: true });
  }
  if (error instanceof Error) throw new DesiaError(error.message, typeof error.code === 'string' ? error.code : 'internal');
  // A bare number is a C++ exception that escaped the bindings' guard: a bug, but never hide it.
  throw new DesiaError(`internal error: uncaught native exception (${String(error)})`, 'internal');
}

/** A short description of a value's type for messages: "a string ('obj')", "an array", "null". */
export function describeValue(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'string') return `a string (${JSON.stringify(value.length > 40 ? `${value.slice(0, 40)}…` : value)})`;
  if (typeof value === 'object') {
    const name = Object.getPrototypeOf(value)?.constructor?.name;
    return name && name !== 'Object' ? `a ${name}` : 'an object';
  }
  if (typeof value === 'bigint') return `a bigint (${value}n)`;
  return `a ${typeof value}${typeof value === 'number' || typeof value === 'boolean' ? ` (${String(value)})` : ''}`;
}

function isPlainObject(value) {
  if (typeof value !== 'object' || value === null) return false;
  const prototype = Object.getPrototypeOf(value);
  return prototype === Object.prototype || prototype === null;
}

function listOf(names) {
  return names.length < 2 ? names.join('') : `${names.slice(0, -1).join(', ')} or ${names.at(-1)}`;
}

/**
 * The options every function with a fixed set takes (the designers' options are the core's to
 * check: it rejects unknown ones itself). The promise-based API adds `signal`.
 */
export const OPTION_NAMES = Object.freeze({
  check: ['method', 'source', 'graphs'],
  parseDocument: ['source'],
  voxelize: ['resolution', 'source'],
  toPuz: ['source'],
  exportAssembly: ['format', 'part', 'voxelSize', 'clearance', 'source', 'sheet', 'sheetIndex', 'kerf', 'spacing', 'hairline'],
  partSurfaces: ['source'],
  cutSheets: ['format', 'sheet', 'kerf', 'spacing', 'hairline', 'source'],
  parseFrame: ['source', 'jointSize'],
  exportFormats: [],
});

/**
 * `options` of function `name`: undefined (none) or a plain object whose keys are all in
 * `accepted` (null: any key). Anything else, e.g. a format string passed where the options go,
 * is a DesiaError rather than a silently ignored value.
 */
export function requireOptions(name, options, accepted = null) {
  if (options === undefined) return {};
  if (!isPlainObject(options)) {
    throw new DesiaError(`${name}: options must be an object, got ${describeValue(options)}`, 'bad-input');
  }
  if (accepted) {
    for (const key of Object.keys(options)) {
      if (!accepted.includes(key)) throw new DesiaError(`${name}: unknown option '${key}' (expected ${listOf(accepted)})`, 'bad-input');
    }
  }
  return options;
}

/** The options as JSON text for the core; values JSON cannot carry are bad input, not dropped. */
function optionsJson(name, options) {
  try {
    return JSON.stringify(options, (key, value) => {
      if (typeof value === 'bigint' || typeof value === 'function' || typeof value === 'symbol') {
        throw new DesiaError(`${name}: option '${key}' must be JSON data (numbers, strings, arrays), got ${describeValue(value)}`, 'bad-input');
      }
      return value;
    });
  } catch (error) {
    if (error instanceof DesiaError) throw error;
    throw new DesiaError(`${name}: the options cannot be written as JSON: ${error?.message ?? error}`, 'bad-input');
  }
}

function requireText(text, what) {
  if (typeof text !== 'string') throw new DesiaError(`${what} must be a string, got ${describeValue(text)}`, 'bad-input');
}

function requireString(value, what) {
  if (typeof value !== 'string') throw new DesiaError(`${what} must be a string, got ${describeValue(value)}`, 'bad-input');
  return value;
}

/**
 * An integer the bindings can take (a C++ int): the value's type, not its meaning, so the core
 * still names the range it accepts.
 */
function requireInt32(value, what) {
  if (!Number.isInteger(value) || Math.abs(value) > 2 ** 31 - 1) {
    throw new DesiaError(`${what} must be an integer (32-bit), got ${describeValue(value)}`, 'bad-input');
  }
  return value;
}

/** A design session's child index: an integer from 0 to 2^31 - 1 (the bindings' unsigned range). */
export function requireChildIndex(method, n) {
  if (!Number.isInteger(n) || n < 0 || n > 2 ** 31 - 1) {
    throw new DesiaError(`designSession: ${method}: the child index must be an integer from 0 to ${2 ** 31 - 1}, got ${describeValue(n)}`, 'bad-input');
  }
  return n;
}

// Mesh input as bytes: a Uint8Array (node's Buffer is one), any other typed-array view or
// ArrayBuffer (viewed without copying), or OBJ text (encoded as UTF-8).
export function meshBytes(input, what) {
  if (input instanceof Uint8Array) return input;
  if (input instanceof ArrayBuffer) return new Uint8Array(input);
  if (ArrayBuffer.isView(input)) return new Uint8Array(input.buffer, input.byteOffset, input.byteLength);
  if (typeof input === 'string') return new TextEncoder().encode(input);
  throw new DesiaError(`${what} must be a Uint8Array, an ArrayBuffer or OBJ text, got ${describeValue(input)}`, 'bad-input');
}

/**
 * Emscripten 3.1.6's ES6 output expects CommonJS globals in node (toolchain.md #6), whatever the
 * module is given: define them before importing it.
 */
async function defineNodeGlobals() {
  const [{ createRequire }, { fileURLToPath }] = await Promise.all([import('node:module'), import('node:url')]);
  globalThis.require ??= createRequire(import.meta.url);
  globalThis.__dirname ??= fileURLToPath(new URL('../dist/', import.meta.url));
}

/** The package's own copy of a module's .wasm file. */
function packagedWasmUrl(which) {
  // Literal URLs, so that bundlers find and ship both files.
  return which === 'light' ? new URL('../dist/desia_light.wasm', import.meta.url) : new URL('../dist/desia_wasm.wasm', import.meta.url);
}

/** A module's factory (Emscripten's ES module). */
function importModuleFactory(which) {
  return which === 'light' ? import('../dist/desia_light.js') : import('../dist/desia_wasm.js');
}

/** node: the loader's fetch fails on file paths there (toolchain.md #3), so pass the bytes. */
async function nodeWasmBinary(wasmUrl, which) {
  const [{ fileURLToPath }, fs] = await Promise.all([import('node:url'), import('node:fs/promises')]);
  const file = wasmUrl === undefined ? fileURLToPath(packagedWasmUrl(which))
    : String(wasmUrl).startsWith('file:') ? fileURLToPath(String(wasmUrl)) : String(wasmUrl);
  return fs.readFile(file);
}

const LOAD_OPTIONS = ['wasmUrl', 'wasmBinary', 'module'];

/** Checks loadDesiaModule's and createDesia's wasmUrl / wasmBinary. */
export function checkLoadOptions(name, { wasmUrl, wasmBinary }) {
  if (wasmUrl !== undefined && typeof wasmUrl !== 'string' && !(wasmUrl instanceof URL)) {
    throw new DesiaError(`${name}: wasmUrl must be a string or a URL, got ${describeValue(wasmUrl)}`, 'bad-input');
  }
  if (wasmBinary !== undefined && !(wasmBinary instanceof ArrayBuffer || ArrayBuffer.isView(wasmBinary))) {
    throw new DesiaError(`${name}: wasmBinary must be an ArrayBuffer or a Uint8Array, got ${describeValue(wasmBinary)}`, 'bad-input');
  }
}

/**
 * Loads a WebAssembly module and returns a synchronous core (use it inside a worker or in node).
 * `module`: 'full' (default: every kind) or 'light' (voxels, contacts, meshes; a plate or frame
 * throws a DesiaError with code 'kind-not-built'); `wasmUrl` / `wasmBinary` are that module's.
 * @param {{wasmUrl?: string|URL, wasmBinary?: ArrayBuffer|Uint8Array, module?: 'light'|'full'}} [options]
 */
export async function loadDesiaModule(options) {
  const { wasmUrl, wasmBinary, module: which = 'full' } = requireOptions('loadDesiaModule', options, LOAD_OPTIONS);
  checkLoadOptions('loadDesiaModule', { wasmUrl, wasmBinary });
  if (!MODULES.includes(which)) {
    throw new DesiaError(`loadDesiaModule: module must be 'light' or 'full', got ${describeValue(which)}`, 'bad-input');
  }
  let module;
  try {
    if (isNode) await defineNodeGlobals();
    const { default: createDesiaModule } = await importModuleFactory(which);
    const moduleOptions = {};
    if (wasmBinary !== undefined) {
      moduleOptions.wasmBinary = wasmBinary;
    } else if (isNode) {
      moduleOptions.wasmBinary = await nodeWasmBinary(wasmUrl, which);
    } else {
      const url = wasmUrl !== undefined ? String(wasmUrl) : packagedWasmUrl(which).href;
      moduleOptions.locateFile = (file) => (file.endsWith('.wasm') ? url : file);
    }
    module = await createDesiaModule(moduleOptions);
  } catch (error) {
    throw new DesiaError(`could not load the desia WebAssembly module: ${error?.message ?? error}${which === 'light' ? ' (the light module)' : ''}`, 'internal');
  }
  return makeCore(module, which);
}

/** The error the light module gives for a call only the full module binds. */
function kindNotBuilt(name) {
  return new DesiaError(`${name}: ${FULL_ONLY[name]}s are in the full desia module (dist/desia_wasm.wasm), not in this light one`, 'kind-not-built');
}

/** Runs one call into the module, turning whatever it throws into a DesiaError. */
function callModule(call) {
  try {
    return call();
  } catch (error) {
    return rethrow(error);
  }
}

function makeCore(module, which) {
  let formats = null;  // the export-format registry, read once
  const requireFullModule = (name) => {
    if (which === 'light') throw kindNotBuilt(name);
  };
  const core = {
    /** Which module this core runs: 'light' or 'full'. */
    module: () => which,
    /** Interlocking check of .puz or JSON text; same fields as `desia check --json`. */
    check(text, options) {
      const { method = 'dbg', source = '<input>', graphs = false } = requireOptions('check', options, OPTION_NAMES.check);
      if (!isMeshDocument(text)) requireText(text, 'check: text');
      requireString(method, 'check: method');
      requireString(source, 'check: source');
      if (typeof graphs !== 'boolean') throw new DesiaError(`check: graphs must be a boolean, got ${describeValue(graphs)}`, 'bad-input');
      if (isMeshDocument(text)) {
        const { names, contents, unit, tolerance } = meshDocumentArguments(text, 'check');
        return callModule(() => module.checkMeshes(names, contents, unit, tolerance, method, graphs));
      }
      return callModule(() => module.check(text, method, source, graphs));
    },
    /** Parses .puz or JSON text into the JSON assembly document (plain object). */
    parseDocument(text, options) {
      const { source = '<input>' } = requireOptions('parseDocument', options, OPTION_NAMES.parseDocument);
      requireText(text, 'parseDocument: text');
      requireString(source, 'parseDocument: source');
      return callModule(() => module.parseDocument(text, source));
    },
    /**
     * Solid voxelization of a closed OBJ or STL mesh into a one-part voxel shape; returns the JSON
     * assembly document (the same as `desia voxelize --output x.json`).
     */
    voxelize(mesh, options) {
      const { resolution = 32, source = '<input>' } = requireOptions('voxelize', options, OPTION_NAMES.voxelize);
      const bytes = meshBytes(mesh, 'voxelize: mesh');
      requireInt32(resolution, 'voxelize: resolution');
      requireString(source, 'voxelize: source');
      return callModule(() => module.voxelize(bytes, resolution, source));
    },
    /** A voxel assembly (.puz text or a JSON document, as text or object) as .puz text. */
    toPuz(assembly, options) {
      const { source = '<input>' } = requireOptions('toPuz', options, OPTION_NAMES.toPuz);
      const text = assemblyText(assembly, 'toPuz: assembly');
      requireString(source, 'toPuz: source');
      return callModule(() => module.toPuz(text, source));
    },
    /**
     * An assembly (text or document object) as a file for other tools: 'stl' (binary), 'stl-ascii',
     * 'obj' or 'xmpuzzle' (BurrTools, voxel puzzles only); for plate structures also 'svg' and 'dxf'
     * cut files (sheet `sheetIndex`, default 0, of those cutSheets makes with the same options);
     * for frame structures 'stl', 'stl-ascii', 'obj', 'fpuz' (FrameInterlock) and 'csv' (cut list).
     * Voxel assemblies print-ready: 'stl-zip' (a ZIP of one STL per part) and 'build-plate-stl'
     * (every part lying flat on z = 0, `spacing` apart, default one voxel).
     * `part` 0 exports every part, k only part k; `voxelSize` scales voxel assemblies (model units
     * per voxel; default: the voxel size a .puz file gives, else 1); `clearance` moves every face between two voxel parts in by that much (below half
     * a voxel). Returns the file's bytes.
     */
    exportAssembly(assembly, options) {
      const { format = 'stl', part = 0, voxelSize, clearance = 0, source = '<input>', sheetIndex = 0, ...cut } =
        requireOptions('exportAssembly', options, OPTION_NAMES.exportAssembly);
      // The core's registry says what each format reads: `spacing` is a cut-sheet option, and the
      // gap between the parts of a build plate.
      const info = core.exportFormats().find((known) => known.name === format);
      const layoutSpacing = info !== undefined && !info.perSheet && info.options.includes('spacing');
      const spacing = layoutSpacing ? cut.spacing : undefined;
      if (layoutSpacing) delete cut.spacing;
      if (info?.perSheet) {
        requireInt32(sheetIndex, 'exportAssembly: sheetIndex');
        const sheets = core.cutSheets(assembly, { format, source, ...cut });
        if (sheetIndex < 0 || sheetIndex >= sheets.length) {
          throw new DesiaError(`exportAssembly: sheetIndex ${sheetIndex} is out of range: the plates fill ${sheets.length} sheet(s)`, 'bad-input');
        }
        return new TextEncoder().encode(sheets[sheetIndex]);
      }
      if (Object.keys(cut).length > 0) {
        throw new DesiaError(`exportAssembly: ${listOf(Object.keys(cut))} apply to 'svg' and 'dxf' cut files only`, 'bad-input');
      }
      const text = assemblyText(assembly, 'exportAssembly: assembly');
      requireString(format, 'exportAssembly: format');
      requireInt32(part, 'exportAssembly: part');
      for (const [name, value] of [['voxelSize', voxelSize ?? 1], ['clearance', clearance], ['spacing', spacing ?? 0]]) {
        if (typeof value !== 'number' || Number.isNaN(value)) {
          throw new DesiaError(`exportAssembly: ${name} must be a number, got ${describeValue(value)}`, 'bad-input');
        }
      }
      requireString(source, 'exportAssembly: source');
      if (typeof module.exportAssembly !== 'function') {
        throw new DesiaError('exportAssembly: this build of the WebAssembly module has no exporter (rebuild dist/ with scripts/build.sh wasm)', 'unsupported');
      }
      // NaN: not given, the core's default (spacing: one voxel; voxelSize: the .puz file's, else 1).
      const bytes = callModule(() => module.exportAssembly(text, format, part, voxelSize ?? NaN, clearance, spacing ?? NaN, source));
      // A view into the module's memory would be detached by the next memory growth: own a copy.
      return bytes.buffer === module.HEAPU8?.buffer ? bytes.slice() : bytes;
    },
    /**
     * The cut files of a plate structure (a design result, text or object): one SVG or DXF text per
     * sheet. Options: `format` 'svg' (default) or 'dxf', `sheet` 'WIDTHxHEIGHT' in mm (default: one
     * sheet as large as needed), `kerf` (mm, outlines out and holes in by half), `spacing` (mm,
     * default 5), `hairline` (SVG strokes 0.01 mm).
     */
    cutSheets(assembly, options) {
      const { format = 'svg', ...rest } = requireOptions('cutSheets', options, OPTION_NAMES.cutSheets);
      const text = assemblyText(assembly, 'cutSheets: assembly');
      requireString(format, 'cutSheets: format');
      requireFullModule('cutSheets');
      if (typeof module.cutSheets !== 'function') {
        throw new DesiaError('cutSheets: this build of the WebAssembly module has no cut files (rebuild dist/ with scripts/build.sh wasm)', 'unsupported');
      }
      const json = optionsJson('cutSheets', rest);
      return callModule(() => module.cutSheets(text, format, json));
    },
    /**
     * The surface of every part of an assembly (text or document object), ready to draw:
     * [{ partId, positions, normals }] in increasing part id, Float32Arrays of non-indexed
     * triangles (9 floats each) with flat outward normals: the triangles of the part's STL/OBJ
     * export. Voxels in voxel units; plates and frames in their model units (a frame without
     * designed joints: its beams, then its bare joint cubes as part 0).
     */
    partSurfaces(assembly, options) {
      const { source = '<input>' } = requireOptions('partSurfaces', options, OPTION_NAMES.partSurfaces);
      requireString(source, 'partSurfaces: source');
      if (typeof module.partSurfaces !== 'function') {
        throw new DesiaError('partSurfaces: this build of the WebAssembly module has no part surfaces (rebuild dist/ with scripts/build.sh wasm)', 'unsupported');
      }
      let surfaces;
      if (isMeshDocument(assembly)) {
        const { names, contents, unit } = meshDocumentArguments(assembly, 'partSurfaces');
        surfaces = callModule(() => module.meshSurfaces(names, contents, unit));
      } else {
        const text = assemblyText(assembly, 'partSurfaces: assembly');
        surfaces = callModule(() => module.partSurfaces(text, source));
      }
      // Views into the module's memory would be detached by the next memory growth: own copies.
      const own = (floats) => (floats.buffer === module.HEAPF32?.buffer ? floats.slice() : floats);
      return surfaces.map(({ partId, positions, normals }) => ({ partId, positions: own(positions), normals: own(normals) }));
    },
    /**
     * Designs an N-part interlocking voxel puzzle from a shape (.puz or JSON text). Resolves to
     * { status, message, progress, puz, document, verification }: `puz` and `document` are set when
     * status is 'success' (the puzzle passed the project's own check); otherwise they are null and
     * `message` says how far the search got. `onProgress(progress)` is called after every visited
     * node; returning false stops the search (status 'cancelled'). The core checks the other
     * options' names and values.
     */
    designVoxel(shapeText, options) {
      const { onProgress, source = '<input>', ...designOptions } = requireOptions('designVoxel', options);
      requireText(shapeText, 'designVoxel: shape');
      requireString(source, 'designVoxel: source');
      if (onProgress !== undefined && typeof onProgress !== 'function') {
        throw new DesiaError('designVoxel: onProgress must be a function', 'bad-input');
      }
      const json = optionsJson('designVoxel', designOptions);
      return callModule(() => module.designVoxel(shapeText, json, source, onProgress));
    },
    /**
     * An interactive design session (the original tool's "Generate Next Part", "Child Index",
     * "Go Back") for a voxel shape or a plate design. It holds WebAssembly memory: call dispose()
     * when done.
     */
    designSession(shapeText, options) {
      const { source = '<input>', ...designOptions } = requireOptions('designSession', options);
      requireText(shapeText, 'designSession: shape');
      requireString(source, 'designSession: source');
      if (designOptions.onProgress !== undefined) {
        throw new DesiaError("designSession: unknown option 'onProgress' (only designVoxel, designPlate and designFrame report progress)", 'bad-input');
      }
      const json = optionsJson('designSession', designOptions);
      let handle;
      try {
        handle = new module.DesignSession(shapeText, json, source);
      } catch (error) {
        rethrow(error);
      }
      const call = (name, ...args) => {
        if (!handle) throw new DesiaError('designSession: the session was disposed', 'bad-input');
        try {
          return handle[name](...args);
        } catch (error) {
          rethrow(error);
        }
      };
      return {
        /** { partsPlaced, targetParts, complete, document } of the current assembly (plates, frames: also steps, message). */
        state: () => call('state'),
        /** Number of ranked children of the current node (generated on first call). */
        childCount: () => call('childCount'),
        /** The JSON document the n-th child (0 = best) would give (plates, frames: the child's step). */
        preview: (n) => call('preview', requireChildIndex('preview', n)),
        /** Move to the n-th child. */
        choose: (n) => call('choose', requireChildIndex('choose', n)),
        /** Move to the best child; false when there is none. */
        next: () => call('next'),
        /** Move to the parent; false at the root. */
        back: () => call('back'),
        /** The check report of the current assembly. */
        check: () => call('check'),
        /**
         * "Finish automatically from here" (voxel, plate and frame sessions): the designer's search below the
         * current node, so the parts placed so far stay as chosen; the session does not move.
         * Options: timeLimit, nodeLimit, onProgress (as designVoxel). Resolves like designVoxel (a
         * plate or frame session: like designPlate or designFrame, the plates or beams taken so far first).
         */
        finish(finishOptions = {}) {
          const { onProgress, ...limits } = requireOptions('designSession: finish', finishOptions);
          if (onProgress !== undefined && typeof onProgress !== 'function') {
            throw new DesiaError('designSession: finish: onProgress must be a function', 'bad-input');
          }
          return call('finish', optionsJson('designSession: finish', limits), onProgress);
        },
        dispose() {
          if (handle) handle.delete();
          handle = null;
        },
      };
    },
    /** Designs the joints of a plate structure (paper Section 5.2); as designFrame. */
    designPlate(input, options) {
      requireFullModule('designPlate');
      return forwardDesigner(module, 'designPlate', 'plate', input, options);
    },
    /**
     * Designs the 3x3x3 voxel joints of a frame structure (paper Section 5.3): the key beam, the
     * order and axis each beam leaves along, the owner of every joint voxel. `input`: a frame as a
     * JSON document (text or object), or OBJ / .fpuz text when `source` ends with .obj / .fpuz.
     * Options (checked by the core): seed, candidates, nodeLimit, timeLimit, jointSize. Same result
     * shape as designPlate; `document` is the CLI's result document for the same seed.
     */
    designFrame(input, options) {
      requireFullModule('designFrame');
      return forwardDesigner(module, 'designFrame', 'frame', input, options);
    },
    /**
     * A frame from JSON (text or object), OBJ (lines and face edges) or .fpuz text (by the
     * extension of `source`) as its checked JSON document (kind 'frame'); `jointSize` > 0 overrides
     * the joint cube size. Throws a DesiaError naming the joint and beams of an invalid frame.
     */
    parseFrame(input, options) {
      const { source = '<input>', jointSize = 0 } = requireOptions('parseFrame', options, OPTION_NAMES.parseFrame);
      const text = assemblyText(input, 'parseFrame: input');
      requireString(source, 'parseFrame: source');
      if (typeof jointSize !== 'number' || !Number.isFinite(jointSize) || jointSize < 0) {
        throw new DesiaError(`parseFrame: jointSize must be a number of model units (0 = from the file or the geometry), got ${describeValue(jointSize)}`, 'bad-input');
      }
      requireFullModule('parseFrame');
      if (typeof module.parseFrame !== 'function') {
        throw new DesiaError('parseFrame: this build of the WebAssembly module has no frame reader (rebuild dist/ with scripts/build.sh wasm)', 'unsupported');
      }
      return callModule(() => module.parseFrame(text, source, jointSize));
    },
    /**
     * Every file format desia writes, from the core's registry (the CLI's `export` asks the same):
     * [{ name, kinds: ['voxel' | 'plate' | 'frame'], options, perSheet, what }].
     */
    exportFormats() {
      formats ??= callModule(() => module.exportFormats());
      return formats.map((format) => ({ ...format, kinds: [...format.kinds], options: [...format.options] }));
    },
    version() {
      return module.version();
    },
  };
  return core;
}

/** A document object as JSON text; text stays text; anything else is refused. */
/**
 * A mesh assembly (issue 29, docs/meshes.md): `{ files: [{ name, bytes | text }], unit?, tolerance? }`
 * — a plain object with a `files` array, which no assembly document has.
 */
export function isMeshDocument(value) {
  return isPlainObject(value) && Array.isArray(value.files);
}

const MESH_DOCUMENT_KEYS = ['files', 'unit', 'tolerance'];

/**
 * A mesh document's values for the bindings (checkMeshes, meshSurfaces): parallel arrays of file
 * names and Uint8Arrays, the unit (default 'mm', the core names a wrong one) and the contact
 * tolerance in mm (default 0: the core's default, scaled to the model).
 */
function meshDocumentArguments(document, name) {
  for (const key of Object.keys(document)) {
    if (!MESH_DOCUMENT_KEYS.includes(key)) throw new DesiaError(`${name}: unknown mesh document field '${key}' (expected ${listOf(MESH_DOCUMENT_KEYS)})`, 'bad-input');
  }
  const { files, unit = 'mm', tolerance = 0 } = document;
  if (files.length === 0) throw new DesiaError(`${name}: a mesh document needs at least one file`, 'bad-input');
  const names = [];
  const contents = [];
  files.forEach((file, k) => {
    const what = `${name}: files[${k}]`;
    if (!isPlainObject(file)) throw new DesiaError(`${what} must be an object { name, bytes } or { name, text }, got ${describeValue(file)}`, 'bad-input');
    names.push(requireString(file.name, `${what}.name`));
    if ((file.bytes === undefined) === (file.text === undefined)) {
      throw new DesiaError(`${what} ('${file.name}') needs either bytes or text`, 'bad-input');
    }
    if (file.text !== undefined) requireText(file.text, `${what}.text`);
    contents.push(meshBytes(file.bytes ?? file.text, `${what}.bytes`));
  });
  requireString(unit, `${name}: unit`);
  if (typeof tolerance !== 'number' || !Number.isFinite(tolerance)) {
    throw new DesiaError(`${name}: tolerance must be a finite number (mm), got ${describeValue(tolerance)}`, 'bad-input');
  }
  return { names, contents, unit, tolerance };
}

function assemblyText(assembly, what) {
  if (isPlainObject(assembly)) {
    try {
      return JSON.stringify(assembly);
    } catch (error) {
      throw new DesiaError(`${what} cannot be written as JSON: ${error?.message ?? error}`, 'bad-input');
    }
  }
  requireText(assembly, what);
  return assembly;
}

/**
 * The plate and frame designers, forwarded like designVoxel to a binding of the same name
 * (`module.designPlate(text, optionsJson, source, onProgress)`) once the core provides one.
 */
function forwardDesigner(module, name, kind, input, options) {
  const { onProgress, source = '<input>', ...designOptions } = requireOptions(name, options);
  if (typeof module[name] !== 'function') {
    throw new DesiaError(`${name}: the ${kind} designer core has not landed yet in this version of desia`, 'unsupported');
  }
  const text = assemblyText(input, `${name}: input`);
  requireString(source, `${name}: source`);
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new DesiaError(`${name}: onProgress must be a function`, 'bad-input');
  }
  const json = optionsJson(name, designOptions);
  try {
    return module[name](text, json, source, onProgress);
  } catch (error) {
    rethrow(error);
  }
}
