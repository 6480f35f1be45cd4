// SPDX-License-Identifier: GPL-3.0-or-later
// A portfolio of voxel designs (issue 10, "all cores"), run by the package's designVoxel with
// `jobs` (wasm/client.js; the playground designs through it). The designer's search is heavy tailed: how long a seed
// takes varies by orders of magnitude, so several searches from different seeds, each in its own
// single-threaded worker, the first verified one winning, use the cores one worker leaves idle.
// The core is unchanged: the winner's result is exactly what one worker with its seed gives, and
// it names that seed (`result.seed`). The native CLI does the same on threads (`--jobs`).

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string' &&
  typeof window === 'undefined' && typeof importScripts === 'undefined';

/** How many workers may run at once here: navigator.hardwareConcurrency, in node os.availableParallelism(). */
export async function availableWorkers() {
  if (isNode) {
    const os = await import('node:os');
    return Math.max(1, os.availableParallelism?.() ?? os.cpus().length);
  }
  return Math.max(1, Number(globalThis.navigator?.hardwareConcurrency) || 1);
}

/** The seeds of a portfolio of `jobs` searches from `seed`: seed, seed + 1, ..., as the CLI's. */
export function portfolioSeeds(seed, jobs) {
  return Array.from({ length: jobs }, (_, k) => seed + k);
}

/** The index of the deepest progress (bestDepth, then depth), the first among equals; -1 if none. */
function deepestIndex(progressList) {
  let best = -1;
  progressList.forEach((progress, k) => {
    if (!progress) return;
    const current = best >= 0 ? progressList[best] : null;
    if (!current || progress.bestDepth > current.bestDepth
      || (progress.bestDepth === current.bestDepth && progress.depth > current.depth)) best = k;
  });
  return best;
}

/**
 * What the caller sees of a portfolio: the deepest search's depths and its `seed`, the nodes of all
 * searches summed, the longest elapsed time. `progressList[k]` is search k's latest progress or null.
 */
export function combineProgress(progressList, seeds) {
  const deepest = deepestIndex(progressList);
  if (deepest < 0) return null;
  const combined = { ...progressList[deepest], seed: seeds[deepest], nodesVisited: 0 };
  for (const progress of progressList) {
    if (!progress) continue;
    combined.nodesVisited += progress.nodesVisited;
    if (progress.elapsedSeconds !== undefined) combined.elapsedSeconds = Math.max(combined.elapsedSeconds ?? 0, progress.elapsedSeconds);
  }
  return combined;
}

/**
 * Runs one search per seed: `runJob(seed, { onProgress, signal }, k)` starts the k-th and resolves
 * with its design result. Resolves with the first result whose status is 'success' and aborts the others
 * (their signals); when none succeeds, with the result of the search that got deepest (the first
 * seed among equals). Rejects with the first error (the others aborted), or with the reason of
 * `signal` when the caller aborts. `onProgress` gets combineProgress of the searches.
 */
export function runPortfolio(seeds, runJob, { signal, onProgress } = {}) {
  return new Promise((resolve, reject) => {
    const controllers = seeds.map(() => new AbortController());
    const progress = seeds.map(() => null);
    const results = seeds.map(() => null);
    let unfinished = seeds.length;
    let settled = false;
    const settle = (action) => {
      if (settled) return;
      settled = true;
      signal?.removeEventListener('abort', onAbort);
      // Only searches still running are stopped (a finished one's worker has nothing to stop).
      controllers.forEach((controller, k) => {
        if (!results[k]) controller.abort();
      });
      action();
    };
    const onAbort = () => settle(() => reject(signal.reason ?? new DOMException('This operation was aborted', 'AbortError')));
    if (signal?.aborted) {
      onAbort();
      return;
    }
    signal?.addEventListener('abort', onAbort, { once: true });
    seeds.forEach((seed, k) => {
      if (settled) return;  // an earlier search failed at once
      const reportProgress = (value) => {
        if (settled) return;
        progress[k] = value;
        onProgress?.(combineProgress(progress, seeds));
      };
      // Started at once, not in a later task: a cancel right after this call reaches every search.
      let started;
      try {
        started = Promise.resolve(runJob(seed, { onProgress: reportProgress, signal: controllers[k].signal }, k));
      } catch (error) {
        started = Promise.reject(error);
      }
      started
        .then((result) => {
          results[k] = result;
          if (result.progress) progress[k] = { ...progress[k], ...result.progress };
          unfinished -= 1;
          if (result.status === 'success') settle(() => resolve(result));
          else if (unfinished === 0) settle(() => resolve(results[Math.max(0, deepestIndex(results.map((r) => r.progress)))]));
        }, (error) => settle(() => reject(error)));
    });
  });
}
