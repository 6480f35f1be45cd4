// SPDX-License-Identifier: GPL-3.0-or-later
// createDesia: the promise-based API of the desia package, the same in browsers and node. It runs
// the core in a worker (wasm/worker.js, a module Web Worker or a worker_threads Worker), or in the
// caller's thread ({ worker: false }), and talks to it with the protocol of wasm/host.js.
// JavaScript only moves messages here: all analysis happens in the C++ core.

import { checkLoadOptions, DesiaError, describeValue, documentedCode, loadDesiaModule, meshBytes, OPTION_NAMES,
  requireChildIndex, requireOptions } from './core.js';
import { createCoreHost, unpackLabels } from './host.js';
import { availableWorkers, portfolioSeeds, runPortfolio } from './portfolio.js';

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string' &&
  typeof window === 'undefined' && typeof importScripts === 'undefined';

/** A worker that has not loaded the core by then is given up (a broken or blocked script). */
const DEFAULT_START_TIMEOUT_MS = 30_000;

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

/**
 * node: the worker inherits the process's options, but `--input-type` (as in
 * `node --input-type=module -e '…'`) makes a worker fail at once: leave it out.
 */
function workerExecArgv() {
  const options = [];
  for (let i = 0; i < process.execArgv.length; i++) {
    const option = process.execArgv[i];
    if (option === '--input-type') i++;
    else if (!option.startsWith('--input-type=')) options.push(option);
  }
  return options;
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
    const worker = new NodeWorker(url, { name: 'desia', execArgv: workerExecArgv() });
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
  /** The WebAssembly modules loaded so far ('light', 'full'), by any of this client's workers. */
  modules = new Set();
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
      clearTimeout(worker.startTimer);
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
    const { wasmUrl, wasmBinary, lightWasmUrl, modules, startTimeout } = this.#options;
    // A worker that never answers (a script that is not the package's, a module that never
    // loads) would leave every call waiting forever: give up on it after startTimeout.
    worker.startTimer = setTimeout(() => this.#onStartTimeout(worker, startTimeout), startTimeout);
    worker.port.post({ type: 'init', wasmUrl, wasmBinary, lightWasmUrl, modules }, []);
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
    clearTimeout(worker.startTimer);
    this.#worker = null;
    worker.rejectReady(new DesiaError('the desia worker was stopped before it was ready', 'terminated'));
    worker.port.terminate();
  }

  #onMessage(worker, message) {
    if (worker !== this.#worker) return; // a late message from a worker we already let go
    const request = this.#inFlight;
    const mine = request !== null && message?.id === request.id;
    switch (message?.type) {
      case 'module':
        this.modules.add(message.module);
        break;
      case 'ready':
        clearTimeout(worker.startTimer);
        worker.isReady = true;
        this.modules.add(message.module ?? 'full');
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
        const error = new DesiaError(String(message.message), documentedCode(message.code), { fatal: message.fatal === true });
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

  #onStartTimeout(worker, timeout) {
    if (worker !== this.#worker || worker.isReady) return;
    const error = new DesiaError(`the desia worker did not load the core within ${timeout / 1000} s `
      + '(is the worker script the package\'s wasm/worker.js, and is dist/desia_wasm.wasm reachable?); the next call starts a new one',
    'internal', { fatal: true });
    worker.rejectReady(error);
    this.#dropWorker();
    if (this.#inFlight) this.#finish(this.#inFlight, error);
    this.#pump();
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

/** The functions that report progress: they take `onProgress` besides `signal`. */
const DESIGNERS = new Set(['designVoxel', 'designPlate', 'designFrame']);

/**
 * Checks a call's options and splits off what the worker cannot receive (functions, signals).
 * Functions with a fixed set of options (core.js OPTION_NAMES) are checked here so the message
 * lists `signal` too; the designers' own options are the core's to check.
 */
function splitOptions(name, options) {
  const fixed = OPTION_NAMES[name];
  const { onProgress, signal, ...coreOptions } = requireOptions(name, options, fixed ? [...fixed, 'signal'] : null);
  if (onProgress !== undefined && !DESIGNERS.has(name)) {
    throw new DesiaError(`${name}: unknown option 'onProgress' (only designVoxel, designPlate and designFrame report progress)`, 'bad-input');
  }
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new DesiaError(`${name}: onProgress must be a function`, 'bad-input');
  }
  if (signal !== undefined && !isAbortSignal(signal)) {
    throw new DesiaError(`${name}: signal must be an AbortSignal, got ${describeValue(signal)}`, 'bad-input');
  }
  return { onProgress, signal, coreOptions };
}

/** designVoxel's `jobs`: a whole number from 1 (default 1). */
function requireJobs(jobs) {
  if (jobs === undefined) return 1;
  if (!Number.isInteger(jobs) || jobs < 1) {
    throw new DesiaError(`designVoxel: jobs must be a whole number from 1, got ${describeValue(jobs)}`, 'bad-input');
  }
  return jobs;
}

/**
 * designVoxel's `liveSurfaces` (true or false, default false): the package's own option, for the
 * host next to the search (wasm/host.js createLiveSurfaces), not the core's.
 */
function requireLiveSurfaces(liveSurfaces) {
  if (liveSurfaces === undefined) return { liveSurfaces: false };
  if (typeof liveSurfaces !== 'boolean') {
    throw new DesiaError(`designVoxel: liveSurfaces must be true or false, got ${describeValue(liveSurfaces)}`, 'bad-input');
  }
  return { liveSurfaces };
}

/**
 * designVoxel with `jobs` > 1: a portfolio of searches (wasm/portfolio.js) with seeds seed,
 * seed + 1, ..., each in a worker of its own (`newClient()`), as many as the machine has cores
 * (availableWorkers; one core: `single()`, the caller's worker). The first verified result wins
 * and the other workers are terminated; the result names its seed. The caller's own worker is
 * left alone (its design sessions live on).
 */
async function designPortfolio(newClient, single, shape, coreOptions, jobs, { signal, onProgress }, live) {
  const count = Math.min(jobs, await availableWorkers());
  if (count === 1) return single();
  const seeds = portfolioSeeds(coreOptions.seed ?? 1, count);
  const clients = [];
  try {
    return await runPortfolio(seeds, (seed, job) => {
      const client = newClient();
      clients.push(client);
      return client.request('designVoxel', [shape, { ...coreOptions, seed }, live], job);
    }, { signal, onProgress });
  } finally {
    await Promise.all(clients.map((client) => client.terminate()));
  }
}

/** session.finish's options: the limits for the core, and onProgress / signal for the client. */
function splitFinishOptions(options) {
  const name = 'designSession: finish';
  const { onProgress, signal, ...coreOptions } = requireOptions(name, options, ['timeLimit', 'nodeLimit', 'onProgress', 'signal']);
  if (onProgress !== undefined && typeof onProgress !== 'function') throw new DesiaError(`${name}: onProgress must be a function`, 'bad-input');
  if (signal !== undefined && !isAbortSignal(signal)) {
    throw new DesiaError(`${name}: signal must be an AbortSignal, got ${describeValue(signal)}`, 'bad-input');
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
  const checkedCall = (method, n) => {
    try {
      requireChildIndex(method, n);
    } catch (error) {
      return Promise.reject(error);
    }
    return call(method, n);
  };
  return {
    state: () => call('state'),
    childCount: () => call('childCount'),
    preview: (n) => checkedCall('preview', n),
    choose: (n) => checkedCall('choose', n),
    next: () => call('next'),
    back: () => call('back'),
    check: () => call('check'),
    finish(finishOptions) {
      let split;
      try {
        split = splitFinishOptions(finishOptions);
      } catch (error) {
        return Promise.reject(error);
      }
      if (disposed) return Promise.reject(new DesiaError('designSession: the session was disposed', 'bad-input'));
      // An abort terminates the worker (a busy one cannot read messages): the session goes with it.
      return client.request('session-finish', [sessionId, split.coreOptions], { session, signal: split.signal, onProgress: split.onProgress });
    },
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
 * The worker loads the light module first and the full one when a plate or frame first needs it
 * (`modules: 'full'`: at once; wasm/host.js). `wasmUrl` / `wasmBinary`: the full module's,
 * `lightWasmUrl`: the light one's (default: the package's dist/; a wasmUrl without it, or a
 * wasmBinary, loads only the full module).
 * @param {{wasmUrl?: string|URL, wasmBinary?: ArrayBuffer|Uint8Array, lightWasmUrl?: string|URL, modules?: 'light-first'|'full', worker?: boolean, workerUrl?: string|URL}} [options]
 */
export async function createDesia(options) {
  const { worker = true, workerUrl, startTimeout = DEFAULT_START_TIMEOUT_MS, wasmBinary, modules = 'light-first' } =
    requireOptions('createDesia', options, ['wasmUrl', 'wasmBinary', 'lightWasmUrl', 'modules', 'worker', 'workerUrl', 'startTimeout']);
  let { wasmUrl, lightWasmUrl } = options ?? {};
  checkLoadOptions('createDesia', { wasmUrl, wasmBinary });
  checkLoadOptions('createDesia', { wasmUrl: lightWasmUrl });
  if (modules !== 'light-first' && modules !== 'full') {
    throw new DesiaError(`createDesia: modules must be 'light-first' or 'full', got ${describeValue(modules)}`, 'bad-input');
  }
  if (typeof worker !== 'boolean') throw new DesiaError(`createDesia: worker must be true or false, got ${describeValue(worker)}`, 'bad-input');
  if (workerUrl !== undefined && typeof workerUrl !== 'string' && !(workerUrl instanceof URL)) {
    throw new DesiaError(`createDesia: workerUrl must be a string or a URL, got ${describeValue(workerUrl)}`, 'bad-input');
  }
  if (typeof startTimeout !== 'number' || !(startTimeout > 0)) {
    throw new DesiaError(`createDesia: startTimeout must be a positive number of milliseconds, got ${describeValue(startTimeout)}`, 'bad-input');
  }
  // The worker resolves URLs against its own script: resolve relative ones against the page.
  const base = !isNode && typeof location === 'object' ? location.href : undefined;
  const absolute = (url) => (url === undefined ? undefined
    : url instanceof URL ? url.href : base ? new URL(String(url), base).href : String(url));
  wasmUrl = absolute(wasmUrl);
  lightWasmUrl = absolute(lightWasmUrl);
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
  const client = new DesiaClient({ wasmUrl, wasmBinary, lightWasmUrl, modules, startTimeout }, startPort);
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
    partSurfaces: simple('partSurfaces'),
    cutSheets: simple('cutSheets'),
    designVoxel(shape, callOptions) {
      let split;
      let jobs;
      try {
        split = splitOptions('designVoxel', callOptions);
        jobs = requireJobs(split.coreOptions.jobs);
      } catch (error) {
        return Promise.reject(error);
      }
      let live;
      try {
        live = requireLiveSurfaces(split.coreOptions.liveSurfaces);
      } catch (error) {
        return Promise.reject(error);
      }
      const coreOptions = { ...split.coreOptions };
      delete coreOptions.jobs;
      delete coreOptions.liveSurfaces;
      const call = { signal: split.signal, onProgress: split.onProgress };
      const single = () => client.request('designVoxel', [shape, coreOptions, live], call);
      // In-process there is one thread: one search.
      if (jobs === 1 || !worker) return single();
      const newClient = () => new DesiaClient({ wasmUrl, wasmBinary, lightWasmUrl, modules, startTimeout }, startPort);
      return designPortfolio(newClient, single, shape, coreOptions, jobs, call, live);
    },
    designPlate: simple('designPlate'),
    designFrame: simple('designFrame'),
    parseFrame: simple('parseFrame'),
    exportFormats: (callOptions) => simple('exportFormats')(undefined, callOptions),
    async designSession(shape, callOptions) {
      const { signal, coreOptions } = splitOptions('designSession', callOptions);

      const { value: sessionId, generation } = await client.request('session-open', [shape, coreOptions], { signal, withGeneration: true });
      return sessionProxy(client, sessionId, generation);
    },
    version: () => client.version,
    /** The WebAssembly modules loaded so far, 'light' first: ['light'], ['light', 'full'] or ['full']. */
    modules: () => ['light', 'full'].filter((name) => client.modules.has(name)),
    terminate: () => client.terminate(),
  };
}
