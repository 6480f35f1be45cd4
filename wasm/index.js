// SPDX-License-Identifier: GPL-3.0-or-later
// The desia package entry point: owns loading of the WebAssembly module in browsers, workers and
// node, so callers need no setup() and no path fiddling. All analysis happens in the C++ core.

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string' &&
  typeof window === 'undefined' && typeof importScripts === 'undefined';

/** Error thrown for bad input and failures; `code` is 'bad-input', 'too-large', 'unsupported' or 'internal'. */
export class DesiaError extends Error {
  constructor(message, code = 'internal', { fatal = false } = {}) {
    super(message);
    this.name = 'DesiaError';
    this.code = code;
    /** True when the WebAssembly instance trapped: load a new module (in a worker: a new worker). */
    this.fatal = fatal;
  }
}

function rethrow(error) {
  if (error instanceof DesiaError) throw error;
  if (typeof WebAssembly === 'object' && error instanceof WebAssembly.RuntimeError) {
    throw new DesiaError(`WebAssembly trap: ${error.message}; this module instance cannot be used again`, 'internal', { fatal: true });
  }
  if (error instanceof Error && typeof error.code === 'string') throw new DesiaError(error.message, error.code);
  if (error instanceof Error) throw new DesiaError(error.message, 'internal');
  // A bare number is a C++ exception that escaped the bindings' guard: a bug, but never hide it.
  throw new DesiaError(`internal error: uncaught native exception (${String(error)})`, 'internal');
}

function requireText(text, what) {
  if (typeof text !== 'string') throw new DesiaError(`${what} must be a string, got ${typeof text}`, 'bad-input');
}

// Mesh input as bytes: a Uint8Array (node's Buffer is one), any other typed-array view or
// ArrayBuffer (viewed without copying), or OBJ text (encoded as UTF-8).
function meshBytes(input, what) {
  if (input instanceof Uint8Array) return input;
  if (input instanceof ArrayBuffer) return new Uint8Array(input);
  if (ArrayBuffer.isView(input)) return new Uint8Array(input.buffer, input.byteOffset, input.byteLength);
  if (typeof input === 'string') return new TextEncoder().encode(input);
  throw new DesiaError(`${what} must be a Uint8Array, an ArrayBuffer or OBJ text, got ${input === null ? 'null' : typeof input}`, 'bad-input');
}

async function nodeWasmBinary(wasmUrl) {
  // Emscripten 3.1.6's ES6 output expects CommonJS globals in node (toolchain.md #6) and its
  // fetch-based loader fails on file paths there (#3): define the globals, pass the bytes.
  const [{ createRequire }, { fileURLToPath }, path, fs] = await Promise.all([
    import('node:module'), import('node:url'), import('node:path'), import('node:fs/promises'),
  ]);
  globalThis.require ??= createRequire(import.meta.url);
  const distDir = fileURLToPath(new URL('../dist/', import.meta.url));
  globalThis.__dirname ??= distDir;
  const file = wasmUrl ? (String(wasmUrl).startsWith('file:') ? fileURLToPath(wasmUrl) : String(wasmUrl))
    : path.join(distDir, 'desia_wasm.wasm');
  return fs.readFile(file);
}

/**
 * Loads the WebAssembly module and returns a synchronous core (use it inside a worker or in node).
 * @param {{wasmUrl?: string|URL, wasmBinary?: ArrayBuffer|Uint8Array}} [options]
 */
export async function loadDesiaModule(options = {}) {
  const { default: createDesiaModule } = await import('../dist/desia_wasm.js');
  const moduleOptions = {};
  if (options.wasmBinary) {
    moduleOptions.wasmBinary = options.wasmBinary;
  } else if (isNode) {
    moduleOptions.wasmBinary = await nodeWasmBinary(options.wasmUrl);
  } else {
    const url = options.wasmUrl ? String(options.wasmUrl) : new URL('../dist/desia_wasm.wasm', import.meta.url).href;
    moduleOptions.locateFile = (file) => (file.endsWith('.wasm') ? url : file);
  }
  let module;
  try {
    module = await createDesiaModule(moduleOptions);
  } catch (error) {
    throw new DesiaError(`could not load the desia WebAssembly module: ${error?.message ?? error}`, 'internal');
  }
  return makeCore(module);
}

function makeCore(module) {
  return {
    /** Interlocking check of .puz or JSON text; same fields as `desia check --json`. */
    check(text, { method = 'dbg', source = '<input>' } = {}) {
      requireText(text, 'check: text');
      try {
        return module.check(text, String(method), String(source));
      } catch (error) {
        rethrow(error);
      }
    },
    /** Parses .puz or JSON text into the JSON assembly document (plain object). */
    parseDocument(text, { source = '<input>' } = {}) {
      requireText(text, 'parseDocument: text');
      try {
        return module.parseDocument(text, String(source));
      } catch (error) {
        rethrow(error);
      }
    },
    /**
     * Solid voxelization of a closed OBJ or STL mesh into a one-part voxel shape; returns the JSON
     * assembly document (the same as `desia voxelize --output x.json`).
     */
    voxelize(mesh, { resolution = 32, source = '<input>' } = {}) {
      const bytes = meshBytes(mesh, 'voxelize: mesh');
      if (!Number.isInteger(resolution) || Math.abs(resolution) > 2 ** 31 - 1) {
        throw new DesiaError(`voxelize: resolution must be an integer (1 to 1024), got ${String(resolution)}`, 'bad-input');
      }
      try {
        return module.voxelize(bytes, resolution, String(source));
      } catch (error) {
        rethrow(error);
      }
    },
    /** A voxel assembly (.puz text or a JSON document, as text or object) as .puz text. */
    toPuz(assembly, { source = '<input>' } = {}) {
      const text = typeof assembly === 'object' && assembly !== null ? JSON.stringify(assembly) : assembly;
      requireText(text, 'toPuz: assembly');
      try {
        return module.toPuz(text, String(source));
      } catch (error) {
        rethrow(error);
      }
    },
    /**
     * Designs an N-part interlocking voxel puzzle from a shape (.puz or JSON text). Resolves to
     * { status, message, progress, puz, document, verification }: `puz` and `document` are set when
     * status is 'success' (the puzzle passed the project's own check); otherwise they are null and
     * `message` says how far the search got. `onProgress(progress)` is called after every visited
     * node; returning false stops the search (status 'cancelled').
     */
    designVoxel(shapeText, { onProgress, source = '<input>', ...options } = {}) {
      requireText(shapeText, 'designVoxel: shape');
      if (onProgress !== undefined && typeof onProgress !== 'function') {
        throw new DesiaError('designVoxel: onProgress must be a function', 'bad-input');
      }
      try {
        return module.designVoxel(shapeText, JSON.stringify(options), String(source), onProgress);
      } catch (error) {
        rethrow(error);
      }
    },
    /**
     * An interactive design session (the original tool's "Generate Next Part", "Child Index",
     * "Go Back"). It holds WebAssembly memory: call dispose() when done.
     */
    designSession(shapeText, { source = '<input>', ...options } = {}) {
      requireText(shapeText, 'designSession: shape');
      let handle;
      try {
        handle = new module.DesignSession(shapeText, JSON.stringify(options), String(source));
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
        /** { partsPlaced, targetParts, complete, document } of the current assembly. */
        state: () => call('state'),
        /** Number of ranked children of the current node (generated on first call). */
        childCount: () => call('childCount'),
        /** The JSON document the n-th child (0 = best) would give. */
        preview: (n) => call('preview', n),
        /** Move to the n-th child. */
        choose: (n) => call('choose', n),
        /** Move to the best child; false when there is none. */
        next: () => call('next'),
        /** Move to the parent; false at the root. */
        back: () => call('back'),
        /** The check report of the current assembly. */
        check: () => call('check'),
        dispose() {
          if (handle) handle.delete();
          handle = null;
        },
      };
    },
    version() {
      return module.version();
    },
  };
}

/**
 * Promise-based API, the same in browsers and node.
 * @param {{wasmUrl?: string|URL, wasmBinary?: ArrayBuffer|Uint8Array}} [options]
 */
export async function createDesia(options = {}) {
  const core = await loadDesiaModule(options);
  return {
    check: async (text, checkOptions) => core.check(text, checkOptions),
    parseDocument: async (text, parseOptions) => core.parseDocument(text, parseOptions),
    voxelize: async (mesh, voxelizeOptions) => core.voxelize(mesh, voxelizeOptions),
    toPuz: async (assembly, toPuzOptions) => core.toPuz(assembly, toPuzOptions),
    designVoxel: async (shapeText, designOptions) => core.designVoxel(shapeText, designOptions),
    designSession: async (shapeText, designOptions) => core.designSession(shapeText, designOptions),
    version: () => core.version(),
  };
}
