// SPDX-License-Identifier: GPL-3.0-or-later
//
// A light first visit (issue 28, item 10). The development server (scripts/serve.mjs) sends
// validators and answers conditional requests with 304, and sends precompressed copies to
// clients that accept them. The published site (scripts/build-site.mjs), served as a host that
// sends its .br/.gz copies would, reaches its first verdict in headless Chromium with an empty
// profile within 1.5 MB, the core's share within 400 KB (the light module: the full one, for
// plates and frames, is not loaded for the default voxel example); the service worker then keeps it for offline use without any file being
// sent twice (it takes what the page loaded from the HTTP cache), and a reload is all 304s but
// for the page itself. The measurement is tests/benchmarks/first_visit_bench.mjs
// (docs/benchmarks.md).
//
//   node --test tests/browser/first-visit.test.mjs

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, rm, utimes, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

import { acceptedEncodings, startServer } from '../../scripts/serve.mjs';
import { measureFirstVisit } from '../benchmarks/first_visit_bench.mjs';
import { checkPrerequisites } from './support.mjs';

/** The budget of the issue: bytes on the wire (bodies as sent plus headers) until the verdict. */
const FIRST_VERDICT_BUDGET = 1.5e6;
/** The budget for the core (module and loader, compressed) before the first verdict. */
const CORE_BUDGET = 400e3;
const LIGHT_CORE = ['/dist/desia_light.wasm', '/dist/desia_light.js'];
const FULL_CORE = ['/dist/desia_wasm.wasm', '/dist/desia_wasm.js'];

describe('the development server: validators and precompressed files', () => {
  let tmp;
  let server;
  const responses = [];
  const body = 'export const answer = 42; // '.padEnd(4000, 'x');

  before(async () => {
    tmp = await mkdtemp(path.join(os.tmpdir(), 'desia-serve-'));
    await writeFile(path.join(tmp, 'index.html'), '<!doctype html><title>t</title>');
    await writeFile(path.join(tmp, 'a.js'), body);
    await writeFile(path.join(tmp, 'a.js.br'), zlib.brotliCompressSync(body));
    await writeFile(path.join(tmp, 'a.js.gz'), zlib.gzipSync(body));
    await writeFile(path.join(tmp, 'stale.js'), body);
    await writeFile(path.join(tmp, 'stale.js.gz'), zlib.gzipSync('old'));
    // The copy is older than the file (the file was rebuilt after it): it must not be sent.
    const past = new Date(Date.now() - 60_000);
    await utimes(path.join(tmp, 'stale.js.gz'), past, past);
    server = await startServer({ port: 0, root: tmp, onResponse: (entry) => responses.push(entry) });
  });

  after(async () => {
    await server?.close();
    if (tmp) await rm(tmp, { recursive: true, force: true });
  });

  const get = (file, headers = {}) => fetch(new URL(file, server.url), { headers: { 'Accept-Encoding': 'identity', ...headers } });

  it('serves another root at /, the repository at /web/', async () => {
    assert.equal(new URL(server.url).pathname, '/');
    assert.equal((await get('/')).status, 200);
    const repo = await startServer({ port: 0 });
    try {
      assert.equal(new URL(repo.url).pathname, '/web/');
      const home = await fetch(new URL('/', repo.url), { redirect: 'manual' });
      assert.equal(home.status, 302);
      assert.equal(home.headers.get('location'), '/web/');
    } finally {
      await repo.close();
    }
  });

  it('sends an ETag and a Last-Modified date, and 304 when they still match', async () => {
    const first = await get('a.js');
    assert.equal(first.status, 200);
    assert.equal(await first.text(), body);
    const etag = first.headers.get('etag');
    const lastModified = first.headers.get('last-modified');
    assert.match(etag, /^"[0-9a-f]+-[0-9a-f]+"$/);
    assert.ok(Number.isFinite(Date.parse(lastModified)));
    assert.equal(first.headers.get('cache-control'), 'no-cache');
    assert.equal(first.headers.get('vary'), 'Accept-Encoding');

    const unchanged = await get('a.js', { 'If-None-Match': etag });
    assert.equal(unchanged.status, 304);
    assert.equal(await unchanged.text(), '');
    assert.equal(unchanged.headers.get('etag'), etag);
    assert.equal((await get('a.js', { 'If-None-Match': `"other", W/${etag}` })).status, 304, 'a list, weak comparison');
    assert.equal((await get('a.js', { 'If-Modified-Since': lastModified })).status, 304);
    assert.equal((await get('a.js', { 'If-None-Match': '"other"' })).status, 200);
    // If-None-Match wins over the date.
    assert.equal((await get('a.js', { 'If-None-Match': '"other"', 'If-Modified-Since': lastModified })).status, 200);
    assert.equal((await get('a.js', { 'If-Modified-Since': new Date(Date.parse(lastModified) - 1000).toUTCString() })).status, 200);
  });

  it('sends the brotli or gzip copy to clients that accept it, with the file\'s type', async () => {
    const br = await get('a.js', { 'Accept-Encoding': 'gzip, deflate, br' });
    assert.equal(br.headers.get('content-encoding'), 'br');
    assert.equal(br.headers.get('content-type'), 'text/javascript; charset=utf-8');
    assert.equal(await br.text(), body, 'decoded by the client');
    const gz = await get('a.js', { 'Accept-Encoding': 'gzip' });
    assert.equal(gz.headers.get('content-encoding'), 'gzip');
    assert.equal(await gz.text(), body);
    const refused = await get('a.js', { 'Accept-Encoding': 'br;q=0, gzip;q=0' });
    assert.equal(refused.headers.get('content-encoding'), null);
    assert.equal(await refused.text(), body);
    // Each encoding is its own entity: its own ETag, revalidated on its own.
    assert.notEqual(br.headers.get('etag'), gz.headers.get('etag'));
    assert.equal((await get('a.js', { 'Accept-Encoding': 'br', 'If-None-Match': br.headers.get('etag') })).status, 304);
    const last = responses.filter((entry) => entry.path === '/a.js' && entry.status === 200).slice(-3);
    assert.deepEqual(last.map((entry) => entry.encoding), ['br', 'gzip', null]);
    assert.ok(last[0].bytes < body.length / 10, 'the compressed size is what is counted as sent');
  });

  it('ignores a copy older than its file', async () => {
    const response = await get('stale.js', { 'Accept-Encoding': 'gzip' });
    assert.equal(response.headers.get('content-encoding'), null);
    assert.equal(await response.text(), body);
  });

  it('reads Accept-Encoding with quality values', () => {
    assert.deepEqual([...acceptedEncodings('gzip, deflate, br, zstd')], ['gzip', 'deflate', 'br', 'zstd']);
    assert.deepEqual([...acceptedEncodings('br;q=0, gzip;q=0.5')], ['gzip']);
    assert.deepEqual([...acceptedEncodings(undefined)], []);
  });
});

describe('the published site\'s first visit in headless Chromium', { timeout: 300_000 }, () => {
  let visit;

  before(async () => {
    checkPrerequisites();
    visit = await measureFirstVisit({ revisit: true });
  });

  it(`shows its first verdict within ${FIRST_VERDICT_BUDGET / 1e6} MB, the core and three.js compressed`, () => {
    assert.ok(visit.beforeVerdict.bytes <= FIRST_VERDICT_BUDGET,
      `${visit.beforeVerdict.bytes} bytes in ${visit.beforeVerdict.responses} responses before the first verdict`);
    for (const file of [...LIGHT_CORE, ...FULL_CORE, '/vendor/three/build/three.core.js', '/main.js', '/']) {
      assert.equal(visit.encodings[file], 'br', `${file} was sent with brotli`);
    }
  });

  it(`loads the light core (at most ${CORE_BUDGET / 1e3} KB) before the first verdict on the default example, the full one only after`, () => {
    const before = visit.log.filter((entry) => entry.ms <= visit.verdictMs && entry.status === 200);
    const coreBytes = before.filter((entry) => LIGHT_CORE.includes(entry.path)).reduce((total, entry) => total + entry.bytes, 0);
    assert.deepEqual(LIGHT_CORE.filter((file) => !before.some((entry) => entry.path === file)), [], 'the light core was loaded');
    assert.ok(coreBytes <= CORE_BUDGET, `the light core: ${coreBytes} bytes`);
    assert.deepEqual(before.filter((entry) => FULL_CORE.includes(entry.path)).map((entry) => entry.path), [],
      'the full core waits for a plate or frame (or the service worker, when idle)');
  });

  it('keeps the playground for offline use, sending no file twice', () => {
    assert.equal(visit.offline.state, 'ready', `offline: ${visit.offline.title}`);
    assert.deepEqual(visit.sentTwice, [], 'files sent twice');
    // Left to fetch: the full core (once) and the examples the page did not open, a few tens of kilobytes.
    const fullCore = visit.log.filter((entry) => FULL_CORE.includes(entry.path) && entry.status === 200);
    assert.deepEqual(fullCore.map((entry) => entry.path).sort(), [...FULL_CORE].sort(), 'the full core kept for offline, once');
    const fullCoreBytes = fullCore.reduce((total, entry) => total + entry.bytes, 0);
    assert.ok(visit.afterOffline.bytes - visit.beforeVerdict.bytes - fullCoreBytes < 200e3,
      `${visit.afterOffline.bytes - visit.beforeVerdict.bytes} bytes after the first verdict, ${fullCoreBytes} of them the full core`);
  });

  it('sends nothing again on a reload but the page: every other file is revalidated (304)', () => {
    assert.equal(visit.revisit.offline, 'ready');
    // The page itself comes again: the service worker passes the reload on, and Chromium's HTTP
    // cache keeps a typed-in navigation apart from a worker's request, so it has no validator
    // to send (5.7 KB with brotli).
    assert.deepEqual(visit.revisit.full.filter((file) => file !== '/'), [], 'files sent in full again');
    assert.ok(visit.revisit.bytes < 50e3, `${visit.revisit.bytes} bytes of headers`);
  });
});
