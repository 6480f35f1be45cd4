// SPDX-License-Identifier: GPL-3.0-or-later
//
// Offline support, the page's side: registers the service worker (web/sw.js) and, once the
// playground has shown its first verdict and the browser is idle, hands it the list of files to
// keep: everything this page loaded (its modules, three.js, the style sheet), the worker's files
// (which the page cannot see load) with the light core, the full core and every bundled example. The files the page and
// its worker loaded are marked as such: the service worker takes them from the browser's HTTP
// cache instead of downloading them again, and fetches only the rest. It keeps them all as one
// snapshot; a small indicator then says whether THIS page works offline: only when it belongs
// to a complete snapshot of its own version (see web/sw.js), never because of an older one.
//
// Only on http(s) pages (service workers need one; a file:// page simply runs online only).
// For tests: body[data-offline] = '' | saving | ready | unavailable, #offline-status.

import { byId } from './dom.js';

/**
 * The package's worker (createDesia's, started as core-worker.js) and everything it imports before
 * the first verdict: the light module (docs/architecture.md). The page's resource list does not
 * show them (the page imports wasm/index.js, client.js, core.js, host.js and portfolio.js itself).
 */
const WORKER_FILES = ['./core-worker.js', '../wasm/worker.js', '../wasm/core.js', '../wasm/host.js', '../dist/desia_light.js', '../dist/desia_light.wasm'];
/**
 * The full module, which the worker loads only for a plate or frame: kept for offline too, fetched
 * with the rest (a revalidation, 304, when the worker has already loaded it).
 */
const FULL_MODULE_FILES = ['../dist/desia_wasm.js', '../dist/desia_wasm.wasm'];
/** The page under both of its names (a link to web/ and to web/index.html). */
const PAGE_FILES = ['./', './index.html'];
const SNAPSHOT_TIMEOUT_MS = 120_000;
/** The snapshot waits for an idle moment, but no longer than this. */
const IDLE_WAIT_MS = 3_000;

function setOfflineState(state, text, title = '') {
  const status = byId('offline-status');
  document.body.dataset.offline = state;
  status.textContent = text;
  status.title = title;
  status.hidden = !text;
}

/** Same-origin files this page has loaded so far, without query or fragment. */
function loadedFiles() {
  const files = [];
  for (const entry of performance.getEntriesByType('resource')) {
    const url = new URL(entry.name);
    // Blob URLs carry this origin too, but are not files: only http(s) requests are kept.
    if (!/^https?:$/.test(url.protocol) || url.origin !== location.origin || url.search) continue;
    url.hash = '';
    files.push(url.href);
  }
  return files;
}

/** The page's own URL when it was loaded as one of `PAGE_FILES` (no query), else nothing. */
function loadedPage() {
  const navigation = performance.getEntriesByType('navigation')[0];
  const url = new URL(navigation?.name ?? location.href);
  if (url.search) return [];
  url.hash = '';
  return PAGE_FILES.map((file) => new URL(file, import.meta.url).href).filter((href) => href === url.href);
}

/** Resolves when the browser is idle (or after IDLE_WAIT_MS), so the snapshot does not compete. */
function idle() {
  return new Promise((resolve) => {
    if (typeof requestIdleCallback === 'function') requestIdleCallback(() => resolve(), { timeout: IDLE_WAIT_MS });
    else setTimeout(resolve, 0);
  });
}

/** Registers the service worker; resolves with the registration, or null where there is none. */
export async function registerServiceWorker() {
  if (!/^https?:$/.test(location.protocol) || !('serviceWorker' in navigator)) return null;
  try {
    return await navigator.serviceWorker.register(new URL('./sw.js', import.meta.url), { scope: './' });
  } catch (error) {
    setOfflineState('unavailable', 'Online only', `The offline cache could not be set up: ${error.message}`);
    return null;
  }
}

/**
 * Asks the active service worker to keep the playground's files; `extraUrls` are files the page
 * may need later (the examples). Updates the indicator with the outcome.
 */
export async function keepForOffline(extraUrls = []) {
  if (!/^https?:$/.test(location.protocol) || !('serviceWorker' in navigator)) return;
  const registration = await navigator.serviceWorker.ready;
  await idle();
  const worker = registration.active;
  if (!worker) return;
  // Loaded by this page or its worker, so already in the browser's HTTP cache.
  const loaded = [
    ...loadedPage(),
    ...WORKER_FILES.map((file) => new URL(file, import.meta.url).href),
    ...loadedFiles(),
  ];
  const urls = [
    ...PAGE_FILES.map((file) => new URL(file, import.meta.url).href),
    ...loaded,
    ...FULL_MODULE_FILES.map((file) => new URL(file, import.meta.url).href),
    ...extraUrls.map((url) => new URL(url, location.href).href),
  ];
  setOfflineState('saving', 'Saving for offline…');
  const channel = new MessageChannel();
  const answer = new Promise((resolve) => {
    const timer = setTimeout(() => resolve({ ok: false, message: 'the service worker did not answer', offline: null }), SNAPSHOT_TIMEOUT_MS);
    channel.port1.onmessage = (event) => {
      clearTimeout(timer);
      resolve(event.data);
    };
  });
  worker.postMessage({ type: 'snapshot', urls, loaded }, [channel.port2]);
  const result = await answer;
  const kept = result.offline;
  if (kept?.justTaken) {
    setOfflineState('ready', 'Available offline', `${kept.files} files (${(kept.bytes / 1048576).toFixed(1)} MiB) kept by the browser`);
  } else if (kept) {
    // This page was itself served from an earlier snapshot (offline, or the server is gone), or
    // belongs to one another tab took after this page loaded: the same version either way.
    const refresh = result.ok ? '' : ` (could not refresh: ${result.message})`;
    setOfflineState('ready', 'Available offline', `Kept on ${new Date(kept.completedAt).toLocaleString()}${refresh}`);
  } else {
    // An older snapshot may exist, but it is not this page's version: it is not offered.
    setOfflineState('unavailable', 'Online only', `Could not keep this version's files for offline use: ${result.message || 'no snapshot'}`);
  }
}
