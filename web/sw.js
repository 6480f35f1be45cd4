// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's service worker: it keeps a snapshot of every file the playground needs (the
// page, its modules, three.js, the WebAssembly core and its loader, the examples) so the page,
// its worker and the examples load with no network at all.
//
// Freshness first: while the network works, requests go to it exactly as without a service
// worker (the worker does not answer them), so a rebuilt core is never mixed with older files.
// The cache answers only when the browser says it is offline, or when the page itself could not
// be fetched a moment ago (a server that is down while the machine is online).
//
// Snapshots are whole: the page sends the list of its files (`{ type: 'snapshot', urls }` with a
// MessagePort); all of them are fetched first, then written to a new cache, which is marked
// complete and replaces the previous one. A failed snapshot leaves the previous one in place, so
// the files served offline always come from one moment, never a new loader with an old .wasm.
// Only GET requests to this origin are ever looked at; anything else is left alone.

/** Bump when the layout of the caches changes: older caches are then deleted on activation. */
const CACHE_FAMILY = 'desia-playground-';
const CACHE_PREFIX = `${CACHE_FAMILY}v1-`;
/** A snapshot without this entry was interrupted and is never used. */
const COMPLETE_MARKER = new URL('./__desia-offline-snapshot__', self.registration.scope).href;
/** After the page could not be fetched, its files come from the cache for this long. */
const NETWORK_DOWN_GRACE_MS = 5 * 60_000;

/** Time until which the network is taken to be down (a navigation failed); 0 = working. */
let networkDownUntil = 0;
/** Snapshots run one at a time (two tabs may ask at once). */
let snapshotQueue = Promise.resolve();

self.addEventListener('install', (event) => {
  // Nothing to wait for: online requests are not answered by this worker, so a new version can
  // take over at once without mixing files.
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

function isOwnGet(request) {
  const url = new URL(request.url);
  return request.method === 'GET' && /^https?:$/.test(url.protocol) && url.origin === self.location.origin;
}

function networkLooksDown() {
  return !self.navigator.onLine || Date.now() < networkDownUntil;
}

self.addEventListener('fetch', (event) => {
  const { request } = event;
  if (!isOwnGet(request)) return;
  if (request.mode === 'navigate') {
    event.respondWith(navigate(request));
  } else if (networkLooksDown()) {
    event.respondWith(fromSnapshot(request));
  }
  // Otherwise: not answered, so the browser fetches it from the network as usual.
});

/** The page itself: from the network when it answers, else from the snapshot. */
async function navigate(request) {
  if (self.navigator.onLine) {
    try {
      const response = await fetch(request);
      networkDownUntil = 0;
      return response;
    } catch {
      networkDownUntil = Date.now() + NETWORK_DOWN_GRACE_MS;
    }
  }
  return fromSnapshot(request);
}

/** The newest complete snapshot, or null. Cache names end in a zero-padded time. */
async function newestSnapshot() {
  const names = (await caches.keys()).filter((name) => name.startsWith(CACHE_PREFIX)).sort().reverse();
  for (const name of names) {
    const cache = await caches.open(name);
    if (await cache.match(COMPLETE_MARKER)) return cache;
  }
  return null;
}

async function fromSnapshot(request) {
  const cache = await newestSnapshot();
  if (cache) {
    // A link's query (?example=…) does not change the page: match the page without it.
    const cached = await cache.match(request)
      ?? (request.mode === 'navigate' ? await cache.match(request, { ignoreSearch: true }) : undefined);
    if (cached) return cached;
  }
  // Not in the snapshot: the network may still answer, or fail just as it would have.
  return fetch(request);
}

/** Fetches every URL, then stores them all as a new complete snapshot; returns its size. */
async function takeSnapshot(urls) {
  const scope = self.registration.scope;
  const unique = [...new Set(urls.map((url) => new URL(url, scope).href))]
    .filter((url) => /^https?:$/.test(new URL(url).protocol) && new URL(url).origin === self.location.origin && url !== COMPLETE_MARKER);
  if (unique.length === 0) throw new Error('no files to keep');
  // `no-cache`: revalidate with the server, so the snapshot is what the server has now.
  const responses = await Promise.all(unique.map(async (url) => {
    const response = await fetch(url, { cache: 'no-cache' });
    if (!response.ok || response.redirected) throw new Error(`${new URL(url).pathname}: HTTP ${response.status}${response.redirected ? ' (redirected)' : ''}`);
    return [url, response];
  }));
  const name = `${CACHE_PREFIX}${String(Date.now()).padStart(16, '0')}`;
  const cache = await caches.open(name);
  let bytes = 0;
  try {
    await Promise.all(responses.map(async ([url, response]) => {
      bytes += Number(response.headers.get('Content-Length') ?? 0);
      await cache.put(url, response);
    }));
    const summary = { files: unique.length, bytes, takenAt: new Date().toISOString() };
    await cache.put(COMPLETE_MARKER, new Response(JSON.stringify(summary), { headers: { 'Content-Type': 'application/json' } }));
  } catch (error) {
    await caches.delete(name);
    throw error;
  }
  for (const other of await caches.keys()) {
    if (other.startsWith(CACHE_PREFIX) && other !== name) await caches.delete(other);
  }
  return { files: unique.length, bytes };
}

self.addEventListener('message', (event) => {
  const port = event.ports?.[0];
  if (event.data?.type !== 'snapshot' || !port || !Array.isArray(event.data.urls)) return;
  const job = snapshotQueue.then(() => takeSnapshot(event.data.urls));
  snapshotQueue = job.catch(() => {});
  event.waitUntil(job.then(
    (summary) => port.postMessage({ ok: true, ...summary }),
    async (error) => port.postMessage({
      ok: false,
      message: String(error?.message ?? error),
      // An earlier snapshot still serves the page offline.
      cached: (await newestSnapshot()) !== null,
    }),
  ));
});
