// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's service worker: it keeps a snapshot of every file the playground needs (the
// page, its modules, three.js, the WebAssembly core and its loader, the examples) so the page,
// its worker and the examples load with no network at all.
//
// Freshness first: while the network works, requests of a page loaded from the network go to it
// exactly as without a service worker (the worker does not answer them). The cache answers them
// only when the browser says it is offline, or when a page could not be fetched a moment ago (a
// server that is down while the machine is online).
//
// Never a mix of versions. Every page (and every worker it starts) belongs to at most one
// snapshot, and cached files are given to it only from that snapshot:
//   - a page served from snapshot X (no network) belongs to X and gets every file from X, even
//     once the network is back, since a newer server would hand it newer modules;
//   - a page loaded from the network belongs to the first snapshot whose fetches started after
//     the page arrived (the one the page asks for right after loading, or one another tab asked
//     for later), never to an older one built from an older server. Until such a snapshot is
//     complete the page belongs to none: with the network gone its requests fail as they would
//     without a service worker, and the page shows its usual error instead of running old files;
//   - a worker belongs to the snapshot of the page that started it (its script request carries
//     the page as clientId and the worker as resultingClientId).
// A snapshot stays while a live page or worker belongs to it, or while it is the newest one
// (which serves pages opened with no network).
//
// Snapshots are whole: the page sends the list of its files (`{ type: 'snapshot', urls, loaded }`
// with a MessagePort); all of them are fetched first, then written to a new cache, which is marked
// complete. A failed snapshot changes nothing. The answer tells the page whether it belongs to a
// complete snapshot, which is what its "Available offline" indicator shows.
//
// Nothing is downloaded twice: the files the page (and its worker) just loaded from the network,
// `loaded`, are read from the browser's HTTP cache, where those requests left them, not fetched
// again; only the rest (the examples the page has not opened) goes to the network, a few at a time
// and at low priority, after the page has shown its first verdict and gone idle (web/offline.js).
//
// What must survive the browser stopping this worker (which clients belong where, the time until
// which the network is taken to be down) is kept as one small JSON entry in the Cache API.
// Only GET requests to this origin are ever looked at; anything else is left alone.

/** Bump when the layout of the caches changes: older caches are then deleted on activation. */
const CACHE_FAMILY = 'desia-playground-';
const CACHE_PREFIX = `${CACHE_FAMILY}v2-`;
/** Snapshot caches: this prefix and the zero-padded time their fetches started (the id). */
const SNAPSHOT_PREFIX = `${CACHE_PREFIX}snapshot-`;
/** The cache holding the persistent state (STATE_URL). */
const STATE_CACHE = `${CACHE_PREFIX}state`;
const STATE_URL = new URL('./__desia-offline-state__', self.registration.scope).href;
/** A snapshot without this entry was interrupted and is never used. */
const COMPLETE_MARKER = new URL('./__desia-offline-snapshot__', self.registration.scope).href;
/** After a page could not be fetched, cached files are used for this long. */
const NETWORK_DOWN_GRACE_MS = 5 * 60_000;
/**
 * A record of a client the Clients API does not list is dropped only after this long: a page
 * whose navigation is under way is not listed yet.
 */
const DEAD_CLIENT_GRACE_MS = 60_000;

/**
 * The persistent state, once read: `networkDownUntil` (ms; 0 = working) and `clients`, by
 * client id: { loadedFrom: 'network' | 'snapshot', loadedAt (ms), snapshot (cache name or null) }.
 */
let state = null;
const stateReady = readState();
/** Writes of the state, in order. */
let stateWrites = Promise.resolve();
/** Snapshots run one at a time (two tabs may ask at once). */
let snapshotQueue = Promise.resolve();
/** Snapshot ids are start times; two snapshots never share one. */
let lastSnapshotStart = 0;

async function readState() {
  let stored = null;
  try {
    const response = await (await caches.open(STATE_CACHE)).match(STATE_URL);
    stored = response ? await response.json() : null;
  } catch {
    stored = null; // unreadable: start afresh (no client belongs to any snapshot)
  }
  state = {
    networkDownUntil: Number(stored?.networkDownUntil) || 0,
    clients: stored?.clients && typeof stored.clients === 'object' ? stored.clients : {},
  };
}

/** Persists the in-memory state; resolves once this version (or a later one) is stored. */
function saveState() {
  const text = JSON.stringify(state);
  stateWrites = stateWrites.then(async () => {
    const cache = await caches.open(STATE_CACHE);
    await cache.put(STATE_URL, new Response(text, { headers: { 'Content-Type': 'application/json' } }));
  }).catch(() => {});
  return stateWrites;
}

self.addEventListener('install', (event) => {
  // Nothing to wait for: a new version starts with no client belonging to a snapshot of its own
  // layout, so it never hands out files of an older one.
  event.waitUntil(self.skipWaiting());
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys()) {
      if (name.startsWith(CACHE_FAMILY) && !name.startsWith(CACHE_PREFIX)) await caches.delete(name);
    }
    await self.clients.claim();
  })());
});

function isOwnUrl(url) {
  const parsed = new URL(url);
  return /^https?:$/.test(parsed.protocol) && parsed.origin === self.location.origin;
}

function networkLooksDown() {
  return !self.navigator.onLine || Date.now() < state.networkDownUntil;
}

self.addEventListener('fetch', (event) => {
  const { request } = event;
  if (request.method !== 'GET' || !isOwnUrl(request.url)) return;
  if (request.mode === 'navigate') {
    event.respondWith(navigate(event));
  } else if (state === null) {
    // Just started, the state is still being read: answer once it is known. Going to the network
    // from here is what the browser would have done.
    event.respondWith(stateReady.then(() => answerSubresource(event) ?? fetch(request)));
  } else {
    const answer = answerSubresource(event);
    if (answer) event.respondWith(answer);
    // Otherwise: not answered, so the browser fetches it from the network as usual.
  }
});

/**
 * The answer to a request of a page or worker, or null to leave it to the network. A worker's
 * script request also makes the new worker belong where its page belongs.
 */
function answerSubresource(event) {
  const { request } = event;
  const owner = state.clients[event.clientId];
  if (event.resultingClientId && owner) {
    state.clients[event.resultingClientId] = { ...owner };
    const saved = saveState();
    try {
      event.waitUntil(saved);
    } catch {
      // Too late to extend the event (the answer was already given): the write still runs.
    }
  }
  if (owner?.loadedFrom === 'snapshot') return fromSnapshot(owner.snapshot, request);
  if (!networkLooksDown()) return null;
  // A page loaded from the network with no snapshot of its own gets no cached file.
  return owner?.snapshot ? fromSnapshot(owner.snapshot, request) : null;
}

/** The file from snapshot `name`; when it is not there, the network answers or fails. */
async function fromSnapshot(name, request) {
  // Gone (the browser evicted it): fail rather than hand this page files of another version.
  if (!(await caches.has(name))) return Response.error();
  // A link's query (?example=…) does not change the page: match the page without it.
  const cached = await caches.match(request, { cacheName: name })
    ?? (request.mode === 'navigate' ? await caches.match(request, { cacheName: name, ignoreSearch: true }) : undefined);
  return cached ?? fetch(request);
}

/** The page itself: from the network when it answers, else from the newest snapshot. */
async function navigate(event) {
  const { request } = event;
  await stateReady;
  if (self.navigator.onLine) {
    try {
      const response = await fetch(request);
      if (event.resultingClientId) {
        state.clients[event.resultingClientId] = { loadedFrom: 'network', loadedAt: Date.now(), snapshot: null };
      }
      state.networkDownUntil = 0;
      await saveState();
      return response;
    } catch {
      state.networkDownUntil = Date.now() + NETWORK_DOWN_GRACE_MS;
      await saveState();
    }
  }
  const newest = await newestSnapshot();
  if (newest) {
    const cached = await caches.match(request, { cacheName: newest })
      ?? await caches.match(request, { cacheName: newest, ignoreSearch: true });
    if (cached) {
      if (event.resultingClientId) {
        state.clients[event.resultingClientId] = { loadedFrom: 'snapshot', loadedAt: Date.now(), snapshot: newest };
        await saveState();
      }
      return cached;
    }
  }
  // No snapshot has it: the network may still answer, or fail just as it would have.
  return fetch(request);
}

/** Names of the snapshot caches, newest first (ids are zero-padded times). */
async function snapshotNames() {
  return (await caches.keys()).filter((name) => name.startsWith(SNAPSHOT_PREFIX)).sort().reverse();
}

/** The complete snapshot's summary, or null when it is missing or was interrupted. */
async function snapshotSummary(name) {
  if (!name || !(await caches.has(name))) return null;
  const marker = await caches.match(COMPLETE_MARKER, { cacheName: name });
  return marker ? marker.json() : null;
}

/** The name of the newest complete snapshot, or null. */
async function newestSnapshot() {
  for (const name of await snapshotNames()) {
    if (await snapshotSummary(name)) return name;
  }
  return null;
}

/** Forgets clients that are gone, then deletes snapshots no one needs. */
async function collectGarbage(keep) {
  const live = new Set((await self.clients.matchAll({ includeUncontrolled: true, type: 'all' })).map((client) => client.id));
  const now = Date.now();
  for (const [id, record] of Object.entries(state.clients)) {
    if (!live.has(id) && now - (Number(record.loadedAt) || 0) > DEAD_CLIENT_GRACE_MS) delete state.clients[id];
  }
  await saveState();
  const needed = new Set([keep, ...Object.values(state.clients).map((record) => record.snapshot)]);
  for (const name of await snapshotNames()) {
    if (!needed.has(name)) await caches.delete(name);
  }
}

/** At most this many of the files the page did not load are fetched at a time. */
const REST_PARALLEL = 3;

/**
 * The response for `url` in a snapshot. A file the page reported as loaded (`fromHttpCache`) is
 * read from the browser's HTTP cache, where the page's own request just left it: the same bytes
 * the page runs, with no second download (the network answers only if the browser dropped it).
 * Any other file is revalidated with the server (`no-cache`: a 304 when the browser's copy is
 * current, else the file), at low priority, so it does not compete with the page.
 */
async function fetchForSnapshot(url, fromHttpCache) {
  const response = await fetch(url, fromHttpCache ? { cache: 'force-cache' } : { cache: 'no-cache', priority: 'low' });
  if (!response.ok || response.redirected) throw new Error(`${new URL(url).pathname}: HTTP ${response.status}${response.redirected ? ' (redirected)' : ''}`);
  return response;
}

/** Calls `work` on each item, at most `limit` at a time; resolves to the results in order. */
async function inBatches(items, limit, work) {
  const results = new Array(items.length);
  let next = 0;
  const runner = async () => {
    while (next < items.length) {
      const index = next;
      next += 1;
      results[index] = await work(items[index]);
    }
  };
  await Promise.all(Array.from({ length: Math.min(limit, items.length) }, runner));
  return results;
}

/**
 * Fetches every URL, then stores them all as a new complete snapshot, to which every page loaded
 * from the network before the fetches started and not yet in a snapshot now belongs. Returns the
 * snapshot's name and summary. `loaded`: URLs the asking page loaded from the network itself
 * (taken from the HTTP cache, see fetchForSnapshot); the others are fetched afterwards, a few
 * at a time. A page and its folder (`x/index.html`, `x/`) are fetched once and kept under both.
 */
async function takeSnapshot(urls, loaded = []) {
  const scope = self.registration.scope;
  const unique = [...new Set(urls.map((url) => new URL(url, scope).href))]
    .filter((url) => isOwnUrl(url) && url !== COMPLETE_MARKER && url !== STATE_URL);
  if (unique.length === 0) throw new Error('no files to keep');
  const wanted = new Set(unique);
  const fromPage = new Set(loaded.map((url) => new URL(url, scope).href).filter((url) => wanted.has(url)));
  const startedAt = Math.max(Date.now(), lastSnapshotStart + 1);
  lastSnapshotStart = startedAt;
  /** `x/index.html` → `x/` when both are wanted: one request for the two names. */
  const aliasOf = (url) => (url.endsWith('/index.html') && wanted.has(url.slice(0, -'index.html'.length)) ? url.slice(0, -'index.html'.length) : url);
  const first = unique.filter((url) => aliasOf(url) === url && fromPage.has(url));
  const rest = unique.filter((url) => aliasOf(url) === url && !fromPage.has(url));
  const fetched = new Map();
  for (const [url, response] of await Promise.all(first.map(async (url) => [url, await fetchForSnapshot(url, true)]))) fetched.set(url, response);
  const later = await inBatches(rest, REST_PARALLEL, async (url) => [url, await fetchForSnapshot(url, false)]);
  for (const [url, response] of later) fetched.set(url, response);
  const responses = unique.map((url) => {
    const source = aliasOf(url);
    return [url, source === url ? fetched.get(url) : fetched.get(source).clone()];
  });
  const name = `${SNAPSHOT_PREFIX}${String(startedAt).padStart(16, '0')}`;
  const cache = await caches.open(name);
  let bytes = 0;
  let summary;
  try {
    // Clones first: a body read by one put() is gone for the other name.
    await Promise.all(responses.map(async ([url, response]) => {
      const body = await response.clone().arrayBuffer();
      bytes += body.byteLength;
      await cache.put(url, response);
    }));
    summary = { files: unique.length, bytes, startedAt, completedAt: Date.now() };
    await cache.put(COMPLETE_MARKER, new Response(JSON.stringify(summary), { headers: { 'Content-Type': 'application/json' } }));
  } catch (error) {
    await caches.delete(name);
    throw error;
  }
  for (const record of Object.values(state.clients)) {
    if (record.loadedFrom === 'network' && !record.snapshot && record.loadedAt <= startedAt) record.snapshot = name;
  }
  await collectGarbage(name);
  return { name, summary };
}

self.addEventListener('message', (event) => {
  const port = event.ports?.[0];
  if (event.data?.type !== 'snapshot' || !port || !Array.isArray(event.data.urls)) return;
  const clientId = event.source?.id;
  const job = snapshotQueue.then(async () => {
    await stateReady;
    // A page this worker never saw load (opened before the worker took control) came from the
    // network, at the latest now: the snapshot about to start is newer than it.
    if (clientId && !state.clients[clientId]) {
      state.clients[clientId] = { loadedFrom: 'network', loadedAt: Date.now(), snapshot: null };
      await saveState();
    }
    // Files the page reports as loaded come from the HTTP cache only for a page that was itself
    // loaded from the network (a page served from a snapshot ran the snapshot's files).
    const fromNetwork = clientId && state.clients[clientId]?.loadedFrom === 'network';
    return takeSnapshot(event.data.urls, fromNetwork && Array.isArray(event.data.loaded) ? event.data.loaded : []);
  });
  snapshotQueue = job.catch(() => {});
  const outcome = job.then(({ name }) => ({ ok: true, name }), (error) => ({ ok: false, message: String(error?.message ?? error) }));
  event.waitUntil(outcome.then(async ({ ok, name = null, message = '' }) => {
    // What the page can rely on offline: the snapshot it belongs to, if any.
    const own = (clientId && state.clients[clientId]?.snapshot) || null;
    const summary = await snapshotSummary(own);
    port.postMessage({ ok, message, offline: summary && { ...summary, justTaken: own === name } });
  }));
});
