// SPDX-License-Identifier: GPL-3.0-or-later
// The desia package entry point. `createDesia()` is the promise-based API, the same in browsers and
// node: it runs the core in a worker (wasm/worker.js, a module Web Worker or a worker_threads
// Worker) and talks to it with the protocol of wasm/host.js. `loadDesiaModule()` loads the
// synchronous core in the calling thread (inside a worker, or in node scripts). This file owns
// loading the WebAssembly module, so callers need no setup() and no path fiddling. All analysis
// happens in the C++ core; JavaScript only moves messages.

import { createCoreHost } from './host.js';

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string' &&
  typeof window === 'undefined' && typeof importScripts === 'undefined';

/**
 * Error thrown for bad input and failures. `code`: from the core 'bad-input', 'too-large',
 * 'unsupported' or 'internal'; from createDesia also 'terminated' (terminate() was called) and
 * 'session-lost' (the worker holding a design session was stopped).
 */
export class DesiaError extends Error {
  constructor(message, code = 'internal', { fatal = false } = {}) {
    super(message);
    this.name = 'DesiaError';
    this.code = code;
    /** True when the WebAssembly instance trapped or the worker died: createDesia replaces it by itself. */
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
      const text = assemblyText(assembly, 'toPuz: assembly');
      try {
        return module.toPuz(text, String(source));
      } catch (error) {
        rethrow(error);
      }
    },
    /**
     * An assembly (text or document object) as a file for other tools: 'stl' (binary), 'stl-ascii',
     * 'obj' or 'xmpuzzle' (BurrTools, voxel puzzles only). `part` 0 exports every part, k only part
     * k; `voxelSize` scales voxel assemblies (model units per voxel). Returns the file's bytes.
     */
    exportAssembly(assembly, { format = 'stl', part = 0, voxelSize = 1, source = '<input>' } = {}) {
      const text = assemblyText(assembly, 'exportAssembly: assembly');
      if (typeof format !== 'string') throw new DesiaError(`exportAssembly: format must be a string, got ${typeof format}`, 'bad-input');
      if (!Number.isInteger(part) || part < 0 || part > 2 ** 31 - 1) {
        throw new DesiaError(`exportAssembly: part must be 0 (every part) or a part id, got ${String(part)}`, 'bad-input');
      }
      if (typeof voxelSize !== 'number' || !Number.isFinite(voxelSize) || voxelSize <= 0) {
        throw new DesiaError(`exportAssembly: voxelSize must be a positive number, got ${String(voxelSize)}`, 'bad-input');
      }
      if (typeof module.exportAssembly !== 'function') {
        throw new DesiaError('exportAssembly: this build of the WebAssembly module has no exporter (rebuild dist/ with scripts/build.sh wasm)', 'unsupported');
      }
      let bytes;
      try {
        bytes = module.exportAssembly(text, format, part, voxelSize, String(source));
      } catch (error) {
        rethrow(error);
      }
      // A view into the module's memory would be detached by the next memory growth: own a copy.
      return bytes.buffer === module.HEAPU8?.buffer ? bytes.slice() : bytes;
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
    /** Designs a plate structure: not available until the plate designer core lands. */
    designPlate(input, options = {}) {
      return forwardDesigner(module, 'designPlate', 'plate', input, options);
    },
    /** Designs a frame structure: not available until the frame designer core lands. */
    designFrame(input, options = {}) {
      return forwardDesigner(module, 'designFrame', 'frame', input, options);
    },
    version() {
      return module.version();
    },
  };
}

/** A document object as JSON text; text stays text; anything else is refused. */
function assemblyText(assembly, what) {
  const text = typeof assembly === 'object' && assembly !== null ? JSON.stringify(assembly) : assembly;
  requireText(text, what);
  return text;
}

/**
 * The plate and frame designers, forwarded like designVoxel to a binding of the same name
 * (`module.designPlate(text, optionsJson, source, onProgress)`) once the core provides one.
 */
function forwardDesigner(module, name, kind, input, { onProgress, source = '<input>', ...options } = {}) {
  if (typeof module[name] !== 'function') {
    throw new DesiaError(`${name}: the ${kind} designer core has not landed yet in this version of desia`, 'unsupported');
  }
  const text = assemblyText(input, `${name}: input`);
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new DesiaError(`${name}: onProgress must be a function`, 'bad-input');
  }
  try {
    return module[name](text, JSON.stringify(options), String(source), onProgress);
  } catch (error) {
    rethrow(error);
  }
}

// ---------------------------------------------------------------------------------------------
// createDesia: the promise-based, worker-backed API.

/** What a call rejects with when its signal aborts without a reason (as fetch does). */
function abortReason(signal) {
  return signal.reason ?? new DOMException('This operation was aborted', 'AbortError');
}

function isAbortSignal(value) {
  return typeof value === 'object' && value !== null && typeof value.aborted === 'boolean'
    && typeof value.addEventListener === 'function';
}

// Mesh bytes for the worker: always our own copy, so moving it to the worker (a transfer) never
// detaches the caller's buffer. (Not .slice(): on a node Buffer that is a view, not a copy.)
function ownMeshBytes(mesh) {
  if (typeof mesh === 'string') return new TextEncoder().encode(mesh);
  const view = meshBytes(mesh, 'voxelize: mesh');
  const copy = new Uint8Array(view.byteLength);
  copy.set(view);
  return copy;
}

/** The host's packed voxel labels (Int32Array) back as the plain array the core returns. */
function unpackLabels(value) {
  for (const document of [value, value?.document]) {
    if (document?.voxel?.labels instanceof Int32Array) document.voxel.labels = Array.from(document.voxel.labels);
  }
  return value;
}

/**
 * Starts the package worker. `handlers.onMessage(message)` gets its messages,
 * `handlers.onFailure(description)` is called once if it dies on its own (uncaught error, trap
 * outside a call, exit). Returns { post, terminate, ref, unref }.
 */
function workerPort(NodeWorker, workerUrl, handlers) {
  if (NodeWorker) {
    const url = workerUrl === undefined ? new URL('./worker.js', import.meta.url)
      : String(workerUrl).startsWith('file:') ? new URL(String(workerUrl)) : String(workerUrl);
    const worker = new NodeWorker(url, { name: 'desia' });
    worker.on('message', handlers.onMessage);
    worker.on('error', (error) => handlers.onFailure(`it crashed: ${error?.message ?? error}`));
    worker.on('messageerror', () => handlers.onFailure('it sent a message that could not be read'));
    worker.on('exit', (code) => handlers.onFailure(`it exited with code ${code}`));
    return {
      post: (message, transfer) => worker.postMessage(message, transfer),
      terminate: () => worker.terminate().then(() => undefined, () => undefined),
      ref: () => worker.ref(),
      unref: () => worker.unref(),
    };
  }
  // The literal `new URL('./worker.js', import.meta.url)` lets bundlers find and ship the worker.
  const worker = workerUrl === undefined
    ? new Worker(new URL('./worker.js', import.meta.url), { type: 'module', name: 'desia' })
    : new Worker(workerUrl, { type: 'module', name: 'desia' });
  worker.addEventListener('message', (event) => handlers.onMessage(event.data));
  worker.addEventListener('error', (event) => {
    event.preventDefault?.();
    // A module worker whose script or imports fail to load gets an error event without a message.
    handlers.onFailure(event.message ? `it crashed: ${event.message}`
      : 'its script or one of its imports failed to load (is dist/desia_wasm.js there?)');
  });
  worker.addEventListener('messageerror', () => handlers.onFailure('it sent a message that could not be read'));
  return {
    post: (message, transfer) => worker.postMessage(message, transfer),
    terminate: async () => worker.terminate(),
    ref: () => {},
    unref: () => {},
  };
}

/**
 * The same host as the worker's, in the caller's thread ({ worker: false }). Messages are
 * structured-cloned both ways, so arguments and results behave exactly as with a worker; each
 * request runs in a task of its own. A running call blocks the thread: an abort can only take
 * effect before it starts, or from inside onProgress (the design then stops at its next node).
 */
function inProcessPort(handlers) {
  let alive = true;
  const host = createCoreHost(loadDesiaModule, (message, transfer) => {
    if (alive) handlers.onMessage(structuredClone(message, { transfer }));
  }, { isCancelled: () => !alive });
  return {
    post(message, transfer) {
      const copy = structuredClone(message, { transfer });
      setTimeout(() => {
        if (alive) host.handle(copy);
      }, 0);
    },
    async terminate() {
      alive = false;
      host.dispose();
    },
    ref: () => {},
    unref: () => {},
  };
}

/**
 * The client side of the protocol. Requests wait in a queue and go to the worker one at a time
 * (it could only run them one after the other anyway), so aborting a queued request costs nothing
 * and aborting the running one loses nothing but that request: the worker is terminated at once
 * and a fresh one is started for the next request.
 */
class DesiaClient {
  #options;
  #startPort;
  /** The live worker: { port, generation, ready, resolveReady, rejectReady, isReady }, or null. */
  #worker = null;
  #generation = 0;
  #queue = [];
  #inFlight = null;
  #nextId = 1;
  version = null;

  constructor(options, startPort) {
    this.#options = options;
    this.#startPort = startPort;
  }

  /** Starts the first worker and waits until its core is loaded. */
  async start() {
    const worker = this.#ensureWorker();
    this.#updateRef();
    try {
      await worker.ready;
    } finally {
      this.#updateRef();
    }
  }

  /**
   * Sends `op` with `args`; resolves with the result. `onProgress` receives progress messages,
   * `signal` aborts, `session` ({ generation }) ties the request to the worker it was opened in,
   * `lostValue` (when set) is what a request for a lost session resolves with instead of failing.
   */
  request(op, args, { transfer = [], onProgress, signal, session, lostValue, withGeneration = false } = {}) {
    return new Promise((resolve, reject) => {
      if (signal?.aborted) {
        reject(abortReason(signal));
        return;
      }
      const request = { id: this.#nextId++, op, args, transfer, onProgress, signal, session, lostValue, withGeneration,
        resolve, reject, onAbort: null, generation: 0 };
      if (signal) {
        request.onAbort = () => this.#abort(request, abortReason(signal));
        signal.addEventListener('abort', request.onAbort, { once: true });
      }
      this.#queue.push(request);
      this.#pump();
    });
  }

  /** Ends the worker; pending requests reject with code 'terminated', sessions are lost. */
  async terminate() {
    const error = new DesiaError('desia was terminated (terminate() was called) before this call finished', 'terminated');
    const pending = [...(this.#inFlight ? [this.#inFlight] : []), ...this.#queue];
    this.#queue = [];
    this.#inFlight = null;
    for (const request of pending) this.#finish(request, error);
    const worker = this.#worker;
    this.#worker = null;
    if (worker) {
      worker.rejectReady(error);
      await worker.port.terminate();
    }
  }

  #ensureWorker() {
    if (this.#worker) return this.#worker;
    const generation = ++this.#generation;
    const worker = { port: null, generation, isReady: false };
    worker.ready = new Promise((resolve, reject) => {
      worker.resolveReady = resolve;
      worker.rejectReady = reject;
    });
    worker.ready.catch(() => {}); // observed by start() and by the requests' own errors
    try {
      worker.port = this.#startPort({
        onMessage: (message) => this.#onMessage(worker, message),
        onFailure: (description) => this.#onFailure(worker, description),
      });
    } catch (error) {
      throw new DesiaError(`could not start the desia worker: ${error?.message ?? error}`, 'internal', { fatal: true });
    }
    this.#worker = worker;
    const { wasmUrl, wasmBinary } = this.#options;
    worker.port.post({ type: 'init', wasmUrl, wasmBinary }, []);
    return worker;
  }

  /** Sends the next queued request when none is running. */
  #pump() {
    while (!this.#inFlight && this.#queue.length > 0) {
      const request = this.#queue.shift();
      if (request.session && this.#worker?.generation !== request.session.generation) {
        if (request.lostValue !== undefined) this.#finish(request, null, request.lostValue);
        else this.#finish(request, sessionLostError());
        continue;
      }
      let worker;
      try {
        worker = this.#ensureWorker();
      } catch (error) {
        this.#finish(request, error);
        continue;
      }
      this.#inFlight = request;
      request.generation = worker.generation;
      try {
        worker.port.post({ type: 'run', id: request.id, op: request.op, args: request.args }, request.transfer);
      } catch (error) {
        // Values that cannot be structured-cloned (functions, class instances with private state).
        this.#inFlight = null;
        this.#finish(request, new DesiaError(`${request.op}: the arguments cannot be sent to the worker: ${error?.message ?? error}`, 'bad-input'));
      }
    }
    this.#updateRef();
  }

  /** node: a worker with nothing to do must not keep the process alive. */
  #updateRef() {
    const port = this.#worker?.port;
    if (!port) return;
    const busy = this.#inFlight !== null || this.#queue.length > 0 || !this.#worker.isReady;
    if (busy) port.ref();
    else port.unref();
  }

  /** Settles a request (error null: resolve with value) and forgets its abort listener. */
  #finish(request, error, value) {
    if (request.onAbort) request.signal.removeEventListener('abort', request.onAbort);
    if (this.#inFlight === request) this.#inFlight = null;
    if (error) request.reject(error);
    else request.resolve(request.withGeneration ? { value, generation: request.generation } : value);
  }

  #abort(request, reason) {
    const queued = this.#queue.indexOf(request);
    if (queued >= 0) {
      this.#queue.splice(queued, 1);
      this.#finish(request, reason);
      this.#updateRef();
      return;
    }
    if (this.#inFlight !== request) return;
    // The worker is busy in WebAssembly and cannot listen: stop it now; the next request starts a
    // fresh one (lazily), and sessions that lived in this one are lost.
    this.#dropWorker();
    this.#finish(request, reason);
    this.#pump();
  }

  #dropWorker() {
    const worker = this.#worker;
    if (!worker) return;
    this.#worker = null;
    worker.rejectReady(new DesiaError('the desia worker was stopped before it was ready', 'terminated'));
    worker.port.terminate();
  }

  #onMessage(worker, message) {
    if (worker !== this.#worker) return; // a late message from a worker we already let go
    const request = this.#inFlight;
    const mine = request !== null && message?.id === request.id;
    switch (message?.type) {
      case 'ready':
        worker.isReady = true;
        this.version ??= message.version;
        worker.resolveReady(message.version);
        this.#updateRef();
        break;
      case 'progress':
        if (mine && request.onProgress) {
          try {
            request.onProgress(message.value);
          } catch (error) {
            // A throwing callback ends its call; the only way to stop the worker is to replace it.
            this.#abort(request, error);
          }
        }
        break;
      case 'result':
        if (mine) {
          this.#finish(request, null, unpackLabels(message.value));
          this.#pump();
        }
        break;
      case 'error': {
        const error = new DesiaError(message.message, message.code ?? 'internal', { fatal: message.fatal === true });
        if (message.id === null || message.id === undefined) {
          // Loading the core failed: this worker is useless.
          worker.rejectReady(error);
          this.#dropWorker();
          if (request) this.#finish(request, error);
          this.#pump();
        } else if (mine) {
          // A trap leaves the instance unusable: replace the worker (its sessions are lost).
          if (error.fatal) this.#dropWorker();
          this.#finish(request, error);
          this.#pump();
        }
        break;
      }
      default:
        break;
    }
  }

  #onFailure(worker, description) {
    if (worker !== this.#worker) return; // terminated by us, or already replaced
    const error = new DesiaError(`the desia worker stopped: ${description}; the next call starts a new one`, 'internal', { fatal: true });
    worker.rejectReady(error);
    this.#dropWorker();
    if (this.#inFlight) this.#finish(this.#inFlight, error);
    this.#pump();
  }
}

function sessionLostError() {
  return new DesiaError('designSession: the session was lost: the worker it lived in was stopped '
    + '(an aborted call, terminate() or a crash); start a new session', 'session-lost');
}

/** Splits the options the worker cannot receive (functions, signals) from the core's options. */
function splitOptions(name, options) {
  const { onProgress, signal, ...coreOptions } = options ?? {};
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new DesiaError(`${name}: onProgress must be a function`, 'bad-input');
  }
  if (signal !== undefined && !isAbortSignal(signal)) {
    throw new DesiaError(`${name}: signal must be an AbortSignal`, 'bad-input');
  }
  return { onProgress, signal, coreOptions };
}

/** The async proxy of a design session living in the worker of `generation`. */
function sessionProxy(client, sessionId, generation) {
  const session = { generation };
  let disposed = false;
  const call = (method, ...args) => {
    if (disposed) return Promise.reject(new DesiaError('designSession: the session was disposed', 'bad-input'));
    return client.request('session-call', [sessionId, method, args], { session });
  };
  return {
    state: () => call('state'),
    childCount: () => call('childCount'),
    preview: (n) => call('preview', n),
    choose: (n) => call('choose', n),
    next: () => call('next'),
    back: () => call('back'),
    check: () => call('check'),
    async dispose() {
      if (disposed) return;
      disposed = true;
      // A lost session has nothing left to free.
      await client.request('session-dispose', [sessionId], { session, lostValue: null });
    },
  };
}

/**
 * The promise-based API, the same in browsers and node. By default the core runs in a worker (a
 * module Web Worker in browsers, a worker_threads Worker in node) started by this call.
 * @param {{wasmUrl?: string|URL, wasmBinary?: ArrayBuffer|Uint8Array, worker?: boolean, workerUrl?: string|URL}} [options]
 */
export async function createDesia(options = {}) {
  const { worker = true, workerUrl } = options ?? {};
  let { wasmUrl, wasmBinary } = options ?? {};
  if (wasmUrl !== undefined) {
    // The worker resolves URLs against its own script: resolve relative ones against the page.
    const base = !isNode && typeof location === 'object' ? location.href : undefined;
    wasmUrl = wasmUrl instanceof URL ? wasmUrl.href : base ? new URL(String(wasmUrl), base).href : String(wasmUrl);
  }
  if (wasmBinary !== undefined && !(wasmBinary instanceof ArrayBuffer || ArrayBuffer.isView(wasmBinary))) {
    throw new DesiaError('createDesia: wasmBinary must be an ArrayBuffer or a Uint8Array', 'bad-input');
  }
  let startPort;
  if (!worker) {
    startPort = inProcessPort;
  } else {
    const NodeWorker = isNode ? (await import('node:worker_threads')).Worker : null;
    if (!NodeWorker && typeof Worker !== 'function') {
      throw new DesiaError('createDesia: this environment has no Worker; pass { worker: false } to run in-process', 'unsupported');
    }
    startPort = (handlers) => workerPort(NodeWorker, workerUrl, handlers);
  }
  const client = new DesiaClient({ wasmUrl, wasmBinary }, startPort);
  await client.start();

  const simple = (name) => (input, callOptions) => {
    let split;
    try {
      split = splitOptions(name, callOptions);
    } catch (error) {
      return Promise.reject(error);
    }
    return client.request(name, [input, split.coreOptions], { signal: split.signal, onProgress: split.onProgress });
  };

  return {
    check: simple('check'),
    parseDocument: simple('parseDocument'),
    voxelize(mesh, callOptions) {
      let bytes;
      let split;
      try {
        bytes = ownMeshBytes(mesh);
        split = splitOptions('voxelize', callOptions);
      } catch (error) {
        return Promise.reject(error);
      }
      return client.request('voxelize', [bytes, split.coreOptions], { transfer: [bytes.buffer], signal: split.signal });
    },
    toPuz: simple('toPuz'),
    exportAssembly: simple('exportAssembly'),
    designVoxel: simple('designVoxel'),
    designPlate: simple('designPlate'),
    designFrame: simple('designFrame'),
    async designSession(shape, callOptions) {
      const { signal, coreOptions } = splitOptions('designSession', callOptions);
      const { value: sessionId, generation } = await client.request('session-open', [shape, coreOptions], { signal, withGeneration: true });
      return sessionProxy(client, sessionId, generation);
    },
    version: () => client.version,
    terminate: () => client.terminate(),
  };
}
