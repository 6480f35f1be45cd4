// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground as a published static site (issue 12), in headless Chromium: the folder that
// `bash scripts/build.sh site` writes (built here by scripts/build-site.mjs, then copied under a
// sub-path of another root, TMP/root/desia/) is served by a plain static file server written
// below (node:http and node:fs, a MIME type per extension, nothing else: not scripts/serve.mjs),
// and the main flow runs at http://127.0.0.1:PORT/desia/: an example is checked, a voxel puzzle
// and a plate plan are designed, a longer design is cancelled, a file is exported (a download),
// and the page reloads with the server stopped and with the browser offline (service worker).
// No request leaves /desia/, and nothing is asked from outside 127.0.0.1.
//
//   node --test tests/browser/site.test.mjs
//
// Needs what playground.test.mjs needs. Screenshots go to test-artifacts/site-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { createReadStream, existsSync } from 'node:fs';
import { cp, lstat, mkdir, mkdtemp, readFile, readdir, rm, stat } from 'node:fs/promises';
import { createServer } from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { chromium } from 'playwright-core';
import { loadDesiaModule } from '../../wasm/index.js';
import {
  ARTIFACTS_DIR, CHROMIUM_ARGS, CHROMIUM_PATH, REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, pageState, screenshot,
  waitForReady,
} from './support.mjs';

const SUB_PATH = '/desia/';
const FIRST_EXAMPLE = 'Cube_4x4x4_K9.puz';
const CUBE_SHAPE = 'Cube_4x4x4_origin.puz';
/** The name the page gives the 7-part puzzle designed from the 4×4×4 cube with seed 1. */
const CUBE_7_SEED_1 = 'Cube_4x4x4_N7_seed1.puz';
const TABLE = 'table.json';
const TABLE_PLAN = 'table_plan_seed1.json';
const DESIGN_TIMEOUT_MS = 30_000;
const SAVE_TIMEOUT_MS = 60_000;

/** What a host has to send: the types a browser insists on for modules, workers and the core. */
const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.wasm': 'application/wasm',
};

/** Everything else (.puz, .obj, .md, LICENSE) as opaque bytes, as a careless host would. */
function mimeType(file) {
  return MIME_TYPES[path.extname(file).toLowerCase()] ?? 'application/octet-stream';
}

/**
 * A plain static file server for `root`: GET and HEAD of files, a folder's index.html (a folder
 * without its trailing slash is redirected to it), 404 for anything else. `stop()` closes it
 * and every open connection, as a server that went away.
 */
async function startStaticServer(root) {
  const requests = [];
  const server = createServer(async (request, response) => {
    const pathname = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
    requests.push(pathname);
    const file = path.join(root, pathname);
    if (!file.startsWith(root + path.sep) && file !== root) {
      response.writeHead(403).end();
      return;
    }
    try {
      let target = file;
      let info = await stat(target);
      if (info.isDirectory()) {
        if (!pathname.endsWith('/')) {
          response.writeHead(301, { Location: `${pathname}/` }).end();
          return;
        }
        target = path.join(target, 'index.html');
        info = await stat(target);
      }
      response.writeHead(200, { 'Content-Type': mimeType(target), 'Content-Length': info.size });
      if (request.method === 'HEAD') response.end();
      else createReadStream(target).pipe(response);
    } catch {
      response.writeHead(404, { 'Content-Type': 'text/plain' }).end('Not found\n');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return {
    origin: `http://127.0.0.1:${port}`,
    requests,
    stop: () => new Promise((resolve) => {
      server.close(() => resolve());
      server.closeAllConnections();
    }),
  };
}

async function listFiles(dir, base = dir) {
  const out = [];
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...await listFiles(full, base));
    else out.push(path.relative(base, full).split(path.sep).join('/'));
  }
  return out.sort();
}

async function designState(page) {
  return page.evaluate(() => ({
    outcome: document.body.dataset.design ?? '',
    core: document.body.dataset.core ?? '',
    message: document.querySelector('#design-message').hidden ? '' : document.querySelector('#design-message').textContent,
    updates: Number(document.querySelector('#design-progress-box').dataset.updates ?? 0),
  }));
}

/** Fills the Design form, clicks Design and waits for the outcome. */
async function design(page, fields) {
  for (const [name, value] of Object.entries(fields)) await page.fill(`#design-form [name="${name}"]`, String(value));
  await page.click('#design-button');
  await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: DESIGN_TIMEOUT_MS });
  return designState(page);
}

describe('the playground as a static site under a sub-path', { timeout: 180_000 }, () => {
  let tmp;
  let siteDir;
  let server;
  let siteUrl;
  let userDataDir;
  let context;
  let page;
  let core;
  const pageErrors = [];
  const requestedUrls = [];
  /** Responses after the server was stopped, and whether the service worker gave them. */
  const responsesWhileDown = [];
  let serverDown = false;

  before(async () => {
    checkPrerequisites([FIRST_EXAMPLE, CUBE_SHAPE]);
    tmp = await mkdtemp(path.join(os.tmpdir(), 'desia-site-'));
    // What `bash scripts/build.sh site` does once the module is built (test.sh built it).
    const built = path.join(tmp, 'build/site');
    const build = spawnSync(process.execPath, [path.join(REPO_ROOT, 'scripts/build-site.mjs'), '--out', built], { encoding: 'utf8' });
    assert.equal(build.status, 0, `build-site failed:\n${build.stdout}${build.stderr}`);
    assert.match(build.stdout, /: \d+ files, \d+\.\d MB \(\d+ bytes; brotli \d+\.\d+ MB, gzip \d+\.\d+ MB/);
    // Published somewhere else, under a sub-path: a plain copy of the folder.
    siteDir = path.join(tmp, 'root', SUB_PATH);
    await mkdir(path.dirname(siteDir), { recursive: true });
    await cp(built, siteDir, { recursive: true });
    server = await startStaticServer(path.join(tmp, 'root'));
    siteUrl = `${server.origin}${SUB_PATH}`;
    core = await loadDesiaModule();
    await mkdir(ARTIFACTS_DIR, { recursive: true });
    userDataDir = await mkdtemp(path.join(os.tmpdir(), 'desia-chromium-'));
    context = await chromium.launchPersistentContext(userDataDir, {
      executablePath: CHROMIUM_PATH,
      headless: true,
      args: CHROMIUM_ARGS,
      viewport: { width: 1280, height: 800 },
      acceptDownloads: true,
    });
    page = context.pages()[0] ?? await context.newPage();
    context.on('request', (request) => requestedUrls.push(request.url()));
    page.on('pageerror', (error) => pageErrors.push(error.message));
    page.on('response', (response) => {
      if (serverDown) responsesWhileDown.push({ url: response.url(), fromServiceWorker: response.fromServiceWorker(), status: response.status() });
    });
  });

  after(async () => {
    await context?.close();
    await server?.stop();
    if (userDataDir) await rm(userDataDir, { recursive: true, force: true });
    if (tmp) await rm(tmp, { recursive: true, force: true });
  });

  it('is one self-contained folder of plain files with relative URLs only', async () => {
    const files = await listFiles(siteDir);
    for (const file of ['index.html', 'main.js', 'sw.js', 'style.css', 'wasm/worker.js', 'wasm/client.js', 'wasm/core.js', 'wasm/host.js', 'wasm/index.js',
      'dist/desia_wasm.js', 'dist/desia_wasm.wasm', 'dist/desia_light.js', 'dist/desia_light.wasm', 'vendor/three/build/three.module.js', 'vendor/three/LICENSE',
      `examples/voxel/${FIRST_EXAMPLE}`, `examples/plate/${TABLE}`, 'examples/meshes/torus.obj', 'examples/embed.html']) {
      assert.ok(files.includes(file), `${file} is missing from the site`);
    }
    assert.deepEqual(files.filter((file) => /(^|\/)\.|\.(py|d\.ts|cpp|txt)$|CMakeLists/.test(file)), [], 'no sources, scripts or hidden files');
    for (const file of files) assert.ok((await lstat(path.join(siteDir, file))).isFile(), `${file} is a plain file`);
    // The core is the one built, byte for byte.
    for (const module of ['dist/desia_wasm.wasm', 'dist/desia_light.wasm']) {
      assert.deepEqual(await readFile(path.join(siteDir, module)), await readFile(path.join(REPO_ROOT, module)));
    }
    // No absolute URL into the repository's layout is left in a page or module.
    for (const file of files.filter((name) => /\.(html|js)$/.test(name) && !name.startsWith('vendor/') && !name.startsWith('dist/'))) {
      const text = await readFile(path.join(siteDir, file), 'utf8');
      assert.doesNotMatch(text, /['"]\/(node_modules|web|wasm|dist|examples)\//, `${file} has a root-absolute URL`);
      assert.doesNotMatch(text, /['"](\.\.\/)+(web|node_modules)\//, `${file} refers to the development layout`);
    }
    // Precompressed copies beside every file (issue 28, item 10), smaller than the file and
    // decompressing to it; the JavaScript minified (three.js ships none).
    const served = files.filter((file) => !/\.(br|gz)$/.test(file));
    let bytes = 0;
    let brotliBytes = 0;
    for (const file of served) {
      const content = await readFile(path.join(siteDir, file));
      bytes += content.length;
      for (const [suffix, unpack] of [['.br', zlib.brotliDecompressSync], ['.gz', zlib.gunzipSync]]) {
        if (!files.includes(file + suffix)) {
          // Left out only where it would not be smaller (a tiny file).
          assert.ok(content.length < 100, `${file}${suffix} is missing`);
          continue;
        }
        const packed = await readFile(path.join(siteDir, file + suffix));
        assert.ok(packed.length < content.length, `${file}${suffix} is not smaller`);
        assert.deepEqual(unpack(packed), content, `${file}${suffix} is not ${file}`);
        if (suffix === '.br') brotliBytes += packed.length;
      }
    }
    assert.deepEqual(files.filter((file) => /\.(br|gz)$/.test(file) && !served.includes(file.slice(0, -3))), [], 'no stray copies');
    const three = await readFile(path.join(siteDir, 'vendor/three/build/three.core.js'), 'utf8');
    assert.ok(three.length < 0.5 * (await stat(path.join(REPO_ROOT, 'node_modules/three/build/three.core.js'))).size, 'three.js is minified');
    assert.match(three, /^\/\*\*?\s*\n?\s*\*?\s*@license/, 'three.js keeps its license comment');
    assert.ok(bytes < 6e6, `the site is ${(bytes / 1e6).toFixed(1)} MB`);
    assert.ok(brotliBytes < 1.5e6, `the site is ${(brotliBytes / 1e6).toFixed(2)} MB with brotli`);
  });

  it('loads at the sub-path and checks the first example', async () => {
    await page.goto(`${siteUrl}?example=${FIRST_EXAMPLE}`);
    const state = await waitForReady(page, FIRST_EXAMPLE);
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '9');
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'ready', 'the worker loaded the core');
    if (state.webgl === 'on') assert.equal(state.meshes, '9', 'three.js drew one mesh per part');
    await screenshot(page, 'site-first-example');
  });

  it('designs a 7-part puzzle from the 4×4×4 cube (seed 1)', async () => {
    await page.selectOption('#example-select', CUBE_SHAPE);
    assert.equal((await waitForReady(page, CUBE_SHAPE)).parts, '1');
    const outcome = await design(page, { parts: 7, seed: 1, timeLimit: 60, workers: 1 });
    assert.equal(outcome.outcome, 'success', `design failed: ${outcome.message}`);
    const state = await waitForReady(page, CUBE_7_SEED_1);
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '7');
  });

  it('cancels a longer design and keeps the page', async () => {
    const before_ = await pageState(page);
    // N = 14 from the 4×4×4 cube runs for tens of seconds (N = 9 now designs within 10 nodes).
    await page.fill('#design-form [name="parts"]', '14');
    await page.fill('#design-form [name="timeLimit"]', '120');
    await page.click('#design-button');
    await page.waitForFunction(() => Number(document.querySelector('#design-progress-box').dataset.updates) >= 3);
    assert.equal((await designState(page)).outcome, 'running');
    await page.click('#design-cancel');
    await page.waitForFunction(
      () => document.body.dataset.design === 'cancelled' && document.body.dataset.status === 'ready'
        && document.body.dataset.core === 'ready' && !document.querySelector('#design-button').disabled,
      null,
      { timeout: 5_000 },
    );
    assert.match((await designState(page)).message, /^Cancelled after/);
    assert.deepEqual(await pageState(page), before_, 'the designed puzzle is still shown');
  });

  it('exports the designed puzzle as a download', async () => {
    await page.selectOption('#export-format', 'stl');
    if (!(await page.locator('#export-part').isDisabled())) await page.selectOption('#export-part', '0');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-button')]);
    assert.match(download.suggestedFilename(), /^Cube_4x4x4_N7_seed1.*\.stl$/);
    const stl = await readFile(await download.path());
    // Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle.
    assert.ok(stl.length > 84);
    assert.equal(stl.length, 84 + 50 * stl.readUInt32LE(80));

    const [puz] = await Promise.all([page.waitForEvent('download'), page.click('#download-button')]);
    assert.equal(puz.suggestedFilename(), CUBE_7_SEED_1);
    const report = core.check(await readFile(await puz.path(), 'utf8'));
    assert.equal(report.verdict, 'interlocking');
    assert.equal(report.key, 1);
  });

  it('plans the joints of the TABLE plate design', async () => {
    await page.selectOption('#example-select', TABLE);
    assert.equal((await waitForReady(page, TABLE)).parts, '6');
    const outcome = await design(page, { seed: 1, timeLimit: 60 });
    assert.equal(outcome.outcome, 'success', `plate design failed: ${outcome.message}`);
    const state = await waitForReady(page, TABLE_PLAN);
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '6');
    await screenshot(page, 'site-table-plan');
  });

  it('serves the embed example: both viewers draw their puzzle under the strict CSP', async () => {
    const embed = await context.newPage();
    const errors = [];
    embed.on('pageerror', (error) => errors.push(error.message));
    embed.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
    try {
      await embed.goto(`${siteUrl}examples/embed.html`);
      for (const selector of ['#cube-nine', '#seven-parts']) {
        await embed.waitForFunction((host) => ['ready', 'error'].includes(document.querySelector(host)?.dataset.state), selector, { timeout: 30_000 });
        const state = await embed.evaluate((host) => {
          const element = document.querySelector(host);
          return { state: element.dataset.state, parts: element.shadowRoot?.querySelector('.viewport')?.dataset.parts ?? '' };
        }, selector);
        assert.equal(state.state, 'ready', `${selector}: ${errors.join('; ')}`);
      }
      assert.match(await embed.textContent('#seven-caption'), /7 parts/);
      assert.deepEqual(errors, []);
    } finally {
      await embed.close();
    }
  });

  it('keeps every file for offline use, all under the sub-path', async () => {
    await page.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: SAVE_TIMEOUT_MS });
    const indicator = await page.evaluate(() => ({
      state: document.body.dataset.offline,
      title: document.querySelector('#offline-status').title,
      controlled: navigator.serviceWorker.controller !== null,
      scope: navigator.serviceWorker.controller && navigator.serviceWorker.controller.scriptURL,
    }));
    assert.equal(indicator.state, 'ready', `offline cache: ${JSON.stringify(indicator)}`);
    assert.equal(indicator.controlled, true, 'the service worker controls the page');
    assert.equal(indicator.scope, `${siteUrl}sw.js`);
    const cached = await page.evaluate(async () => {
      const urls = new Set();
      for (const name of await caches.keys()) {
        for (const request of await (await caches.open(name)).keys()) urls.add(request.url);
      }
      return [...urls];
    });
    for (const file of ['', 'index.html', 'wasm/worker.js', 'wasm/core.js', 'dist/desia_light.wasm', 'dist/desia_wasm.wasm', 'vendor/three/build/three.module.js',
      'vendor/three/build/three.core.js', `examples/voxel/${CUBE_SHAPE}`, 'examples/meshes/torus.obj']) {
      assert.ok(cached.includes(`${siteUrl}${file}`), `${SUB_PATH}${file} is not kept for offline use`);
    }
    assert.deepEqual(cached.filter((url) => !url.startsWith(siteUrl)), [], 'cached outside the sub-path');
  });

  it('reloads, restarts its worker and checks with the server stopped, then with the browser offline', async () => {
    await server.stop();
    serverDown = true;
    await page.goto(`${siteUrl}?example=${FIRST_EXAMPLE}`);
    assertInterlockingWithKey(await waitForReady(page, FIRST_EXAMPLE), 1);
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'ready', 'the worker loaded the core from the cache');
    await page.selectOption('#example-select', CUBE_SHAPE);
    assert.equal((await waitForReady(page, CUBE_SHAPE)).parts, '1');

    await context.setOffline(true);
    await page.reload();
    assert.equal((await waitForReady(page, CUBE_SHAPE)).parts, '1');
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'ready');
    // A design offline: the worker and the core came from the snapshot.
    const outcome = await design(page, { parts: 7, seed: 1, timeLimit: 60, workers: 1 });
    assert.equal(outcome.outcome, 'success', `offline design failed: ${outcome.message}`);
    assertInterlockingWithKey(await waitForReady(page, CUBE_7_SEED_1), 1);
    await screenshot(page, 'site-offline');
    assert.ok(responsesWhileDown.length > 0);
    assert.deepEqual(responsesWhileDown.filter((response) => !response.fromServiceWorker), [], 'responses not from the service worker');
    // Voxel examples only: the light module (docs/architecture.md).
    for (const file of ['main.js', 'wasm/worker.js', 'dist/desia_light.wasm', 'vendor/three/build/three.module.js']) {
      assert.ok(responsesWhileDown.some((response) => response.url === `${siteUrl}${file}`), `${file} was served offline`);
    }
  });

  it('asked nothing outside the sub-path and threw no page errors', () => {
    assert.ok(server.requests.length > 0);
    assert.deepEqual(server.requests.filter((pathname) => !pathname.startsWith(SUB_PATH)), [], 'the server saw requests outside the sub-path');
    const elsewhere = requestedUrls.filter((url) => !url.startsWith(siteUrl) && !/^(data|blob):/.test(url));
    assert.deepEqual(elsewhere, [], 'requests outside the site');
    assert.deepEqual(pageErrors, []);
    assert.ok(existsSync(siteDir));
  });
});
