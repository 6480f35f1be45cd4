// SPDX-License-Identifier: GPL-3.0-or-later
//
// The page's side of the worker protocol (see worker.js): request/response with progress, crash
// recovery, and cancellation. A busy single-threaded WebAssembly worker cannot read a 'cancel'
// message, so cancel() terminates the worker and starts a fresh one at once.

import { portfolioSeeds, runPortfolio } from '../wasm/portfolio.js';

/** A worker that has not reported `ready` by then is considered dead. */
const WORKER_START_TIMEOUT_MS = 30_000;
/** Consecutive failed worker starts before we stop restarting on our own. */
export const MAX_FAILED_STARTS = 3;

/** The rejection of requests that were cancelled (not a failure: nothing to report). */
export class CancelledError extends Error {
  constructor(message = 'cancelled') {
    super(message);
    this.name = 'CancelledError';
    this.cancelled = true;
  }
}

export class CoreWorker {
  #worker = null;
  #pending = new Map();
  #nextId = 1;
  #failedStarts = 0;
  #ready = false;
  #startTimer = 0;
  #generation = 0;
  #onStart;
  #onReady;
  #onCrash;

  /**
   * `onStart()` when a worker starts (first time, after a crash or a cancel), `onReady(version)`
   * once it has loaded the core, `onCrash(message, willRestart)` when one dies.
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

  start() {
    const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.#worker = worker;
    this.#ready = false;
    this.#generation += 1;
    worker.addEventListener('message', (event) => {
      if (worker === this.#worker) this.#handleMessage(event.data);
    });
    worker.addEventListener('error', (event) => {
      // Keep the failure out of the console's "uncaught" list: we report it ourselves.
      event.preventDefault();
      if (worker !== this.#worker) return;
      // A module worker that fails to load its imports gets an error event without a message.
      const detail = event.message || 'the worker script or one of its imports failed to load '
        + '(is the WebAssembly build there? run: bash scripts/build.sh wasm)';
      this.#crash(`worker crashed: ${detail}`);
    });
    worker.addEventListener('messageerror', () => {
      if (worker === this.#worker) this.#crash('worker sent a message the page could not read');
    });
    clearTimeout(this.#startTimer);
    this.#startTimer = setTimeout(() => {
      if (worker === this.#worker) this.#crash(`the WebAssembly core did not start within ${WORKER_START_TIMEOUT_MS / 1000} s`);
    }, WORKER_START_TIMEOUT_MS);
    worker.postMessage({ type: 'init' });
    this.#onStart();
  }

  /**
   * Runs `op` (see worker.js) on `text`; resolves with `{ value, elapsedMs }`. `onProgress(value)`
   * receives the worker's progress messages for this request. `bytes` (a Uint8Array, e.g. a mesh)
   * is copied to the worker, so the caller keeps its own copy for the next request.
   */
  run(op, text, options = {}, { onProgress, bytes } = {}) {
    if (!this.#worker) {
      // stop() was called, or we gave up restarting after repeated failures; a new request is
      // worth one more try.
      this.#failedStarts = 0;
      this.start();
    }
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve, reject, onProgress });
      const message = { type: 'run', id, op, text, options };
      if (bytes !== undefined) message.bytes = bytes;
      this.#worker.postMessage(message);
    });
  }

  /**
   * Stops whatever the worker is doing within a moment: terminates it, rejects every pending
   * request with a CancelledError, and starts a fresh worker (which loses any design session).
   */
  cancel() {
    this.#discardWorker(new CancelledError());
    this.start();
  }

  /**
   * Like cancel(), without starting a fresh worker: the next request starts one. For helper
   * workers that need not sit loaded while nothing runs.
   */
  stop() {
    this.#discardWorker(new CancelledError());
  }

  #handleMessage(message) {
    switch (message?.type) {
      case 'ready':
        clearTimeout(this.#startTimer);
        this.#ready = true;
        this.#failedStarts = 0;
        this.#onReady(message.version);
        break;
      case 'progress':
        this.#pending.get(message.id)?.onProgress?.(message.value);
        break;
      case 'result':
        this.#settle(message.id, (request) => request.resolve({ value: message.value, elapsedMs: message.elapsedMs }));
        break;
      case 'error':
        if (message.id === null || message.id === undefined) {
          this.#crash(message.message);
          break;
        }
        this.#settle(message.id, (request) => request.reject(Object.assign(new Error(message.message), message.code ? { code: message.code } : {})));
        // The module trapped or aborted: its state is gone, so is its usefulness.
        if (message.fatal) this.#crash(message.message);
        break;
      default:
        console.warn('desia playground: unexpected worker message', message);
    }
  }

  #settle(id, action) {
    const request = this.#pending.get(id);
    if (!request) return;
    this.#pending.delete(id);
    action(request);
  }

  /** Terminates the worker and rejects everything it still owed us with `error`. */
  #discardWorker(error) {
    clearTimeout(this.#startTimer);
    this.#worker?.terminate();
    this.#worker = null;
    const requests = [...this.#pending.values()];
    this.#pending.clear();
    for (const request of requests) request.reject(error);
  }

  /** Throws the worker away, fails what it still owed us, and starts a fresh one if sensible. */
  #crash(message) {
    // Only failures before `ready` count towards giving up: a worker that ran fine and then
    // crashed on one input deserves a fresh start every time.
    if (!this.#ready) this.#failedStarts += 1;
    this.#discardWorker(new Error(message));
    const willRestart = this.#failedStarts < MAX_FAILED_STARTS;
    this.#onCrash(message, willRestart);
    if (willRestart) this.start();
  }
}

/**
 * Voxel designs on several workers at once (issue 10, "all cores"; wasm/portfolio.js): search k
 * runs with seed + k, the first in the page's own worker and the others in helper workers. The
 * first verified puzzle wins and the other searches are stopped: a helper's worker is terminated
 * (a run starts it again), the page's own is cancelled (a fresh one starts at once; a step-by-step
 * session in it ends, as with Cancel).
 */
export class WorkerPortfolio {
  #workers;

  /** `main`: the page's CoreWorker, which runs the first search. */
  constructor(main) {
    this.#workers = [main];
  }

  /**
   * Runs `op` ('design') with `options` in `jobs` workers; resolves with `{ value, elapsedMs }`
   * of the winner (`value.seed` names its seed) or, when none succeeds, of the deepest search.
   * `onProgress` gets the deepest search's progress with its `seed` and all searches' nodes.
   * Every search is sent before this returns, so cancel() right after reaches them all.
   */
  run(op, text, options, jobs, { onProgress } = {}) {
    while (this.#workers.length < jobs) {
      // A helper's failure fails its search, and with it the run: nothing more to report. Its
      // worker starts with its first request.
      this.#workers.push(new CoreWorker({ onReady: () => {}, onCrash: () => {} }));
    }
    const seeds = portfolioSeeds(options.seed ?? 1, jobs);
    const elapsed = new Map();
    return runPortfolio(seeds, (seed, job, k) => {
      const worker = this.#workers[k];
      job.signal.addEventListener('abort', () => this.#halt(k), { once: true });
      return worker.run(op, text, { ...options, seed }, { onProgress: job.onProgress }).then((answer) => {
        elapsed.set(seed, answer.elapsedMs);
        return answer.value;
      });
    }, { onProgress }).then((value) => ({ value, elapsedMs: elapsed.get(value.seed) }));
  }

  /** Stops every search within a moment; the running request rejects with a CancelledError. */
  cancel() {
    this.#workers.forEach((_, k) => this.#halt(k));
  }

  #halt(k) {
    if (k === 0) this.#workers[0].cancel();
    else this.#workers[k].stop();
  }
}
