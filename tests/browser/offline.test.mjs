// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground offline in headless Chromium: after one visit the service worker (web/sw.js)
// holds every file the playground needs; with the server gone, and then with the browser
// offline as well, a reload still shows the page, its worker loads the WebAssembly core from the
// cache, and examples (a puzzle, a shape and a mesh) are checked and voxelized.
//
//   node --test tests/browser/offline.test.mjs
//
// A second browser checks that versions never mix: a page loaded from the network after the last
// snapshot, whose own snapshot failed, does not claim to work offline, and offline its restarted
// worker fails clearly instead of running the older snapshot's files; a page of that older
// snapshot's time, in the same browser, still restarts its worker offline from it.
//
// Needs what playground.test.mjs needs. Screenshots go to test-artifacts/offline-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFile, readdir } from 'node:fs/promises';
import path from 'node:path';
import {
  REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, screenshot, waitForReady,
} from './support.mjs';

const FIRST_EXAMPLE = 'Cube_4x4x4_K9.puz';
const SHAPE_EXAMPLE = 'Cube_4x4x4_origin.puz';
const SAVE_TIMEOUT_MS = 60_000;

/**
 * Every module the page imports, directly or not, found by reading the import statements from
 * web/main.js on (relative imports only; `three` is checked on its own).
 */
async function pageModules() {
  const found = new Set();
  const queue = ['main.js'];
  while (queue.length > 0) {
    const file = queue.pop();
    if (found.has(file)) continue;
    found.add(file);
    const source = await readFile(path.join(REPO_ROOT, 'web', file), 'utf8');
    for (const [, target] of source.matchAll(/\bfrom\s+'\.\/([\w-]+\.js)'/g)) queue.push(target);
  }
  return [...found].sort();
}

/** A file the server does not have: asking the service worker to keep it makes the snapshot fail. */
const MISSING_FILE = '__no-such-file__.js';
/** The offline indicator. */
async function offlineIndicator(page) {
  return page.evaluate(() => ({
    state: document.body.dataset.offline,
    text: document.querySelector('#offline-status').textContent,
    title: document.querySelector('#offline-status').title,
  }));
}

/**
 * Makes the page start a fresh worker the way a user does: Design, then Cancel at once (in one
 * task, so the design cannot finish in between; Cancel terminates the busy worker).
 */
async function restartWorkerWithCancel(page) {
  await page.evaluate(() => {
    document.querySelector('#design-button').click();
    document.querySelector('#design-cancel').click();
  });
  await page.waitForFunction(() => document.body.dataset.design === 'cancelled');
}

/** The URLs in the newest complete snapshot of the service worker's caches. */
async function cachedUrls(page) {
  return page.evaluate(async () => {
    const urls = new Set();
    for (const name of await caches.keys()) {
      if (!name.startsWith('desia-playground-')) continue;
      const cache = await caches.open(name);
      for (const request of await cache.keys()) urls.add(request.url);
    }
    return [...urls];
  });
}

describe('playground offline in headless Chromium', { timeout: 120_000 }, () => {
  let browser;
  let server;
  let context;
  let page;
  const pageErrors = [];
  /** Responses after the server was stopped, and whether the service worker gave them. */
  const responsesWhileDown = [];
  let serverDown = false;

  before(async () => {
    checkPrerequisites([FIRST_EXAMPLE, SHAPE_EXAMPLE]);
    browser = await openBrowser();
    ({ server, context, page } = browser);
    page.on('pageerror', (error) => pageErrors.push(error.message));
    page.on('response', (response) => {
      if (serverDown) responsesWhileDown.push({ url: response.url(), fromServiceWorker: response.fromServiceWorker(), status: response.status() });
    });
  });

  after(async () => {
    await browser?.close();
  });

  it('keeps every file of the playground once it has loaded', async () => {
    await page.goto(`${server.url}?example=${FIRST_EXAMPLE}`);
    assertInterlockingWithKey(await waitForReady(page, FIRST_EXAMPLE), 1);
    await page.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: SAVE_TIMEOUT_MS });
    const indicator = await page.evaluate(() => ({
      state: document.body.dataset.offline,
      text: document.querySelector('#offline-status').textContent,
      hidden: document.querySelector('#offline-status').hidden,
      controlled: navigator.serviceWorker.controller !== null,
    }));
    assert.equal(indicator.state, 'ready', `offline cache: ${JSON.stringify(indicator)}`);
    assert.equal(indicator.text, 'Available offline');
    assert.equal(indicator.hidden, false);
    assert.equal(indicator.controlled, true, 'the service worker controls the page');
    await screenshot(page, 'offline-saved');

    const cached = new Set(await cachedUrls(page));
    const origin = new URL(server.url).origin;
    const expected = [
      '/web/', '/web/index.html', '/web/style.css',
      ...(await pageModules()).map((file) => `/web/${file}`),
      // The package the page runs on (createDesia) and its worker.
      '/web/core-worker.js', '/wasm/index.js', '/wasm/client.js', '/wasm/portfolio.js', '/wasm/worker.js', '/wasm/core.js', '/wasm/host.js', '/dist/desia_light.js', '/dist/desia_light.wasm',
      // The full module too (for plates and frames), fetched when the page was idle.
      '/dist/desia_wasm.js', '/dist/desia_wasm.wasm',
      '/node_modules/three/build/three.module.js',
      ...(await readdir(path.join(REPO_ROOT, 'examples/voxel'))).filter((file) => file.endsWith('.puz')).map((file) => `/examples/voxel/${file}`),
      '/examples/meshes/torus.obj',
    ];
    const missing = expected.filter((file) => !cached.has(`${origin}${file}`));
    assert.deepEqual(missing, [], 'files the offline playground would lack');
    assert.ok([...cached].every((url) => url.startsWith(`${origin}/`)), 'only this origin is cached');
  });

  it('loads, starts its worker and checks examples with the server gone', async () => {
    await server.stop();
    serverDown = true;
    await page.reload();
    assertInterlockingWithKey(await waitForReady(page, FIRST_EXAMPLE), 1);
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'ready', 'the worker loaded the core');
    // The browser may stop an idle service worker at any time: what it knows about this page
    // (served from the snapshot) must survive that.
    const devtools = await context.newCDPSession(page);
    await devtools.send('ServiceWorker.enable');
    await devtools.send('ServiceWorker.stopAllWorkers');
    await devtools.detach();
    await page.selectOption('#example-select', SHAPE_EXAMPLE);
    const shape = await waitForReady(page, SHAPE_EXAMPLE);
    assert.equal(shape.parts, '1');
  });

  it('loads, starts its worker, checks and voxelizes examples with the browser offline', async () => {
    await context.setOffline(true);
    assert.equal(await page.evaluate(() => navigator.onLine), false);
    await page.goto(`${server.url}?example=${SHAPE_EXAMPLE}`);
    const shape = await waitForReady(page, SHAPE_EXAMPLE);
    assert.equal(shape.parts, '1');
    assert.equal(await page.evaluate(() => document.body.dataset.core), 'ready', 'the worker loaded the core');
    await page.selectOption('#example-select', FIRST_EXAMPLE);
    const puzzle = await waitForReady(page, FIRST_EXAMPLE);
    assertInterlockingWithKey(puzzle, 1);
    assert.equal(puzzle.parts, '9');
    await page.selectOption('#example-select', 'torus.obj');
    await page.fill('#mesh-resolution', '16');
    const torus = await waitForReady(page, 'torus_r16.json');
    assert.equal(torus.parts, '1');
    // The indicator still says so: the snapshot of the first visit is serving the page.
    await page.waitForFunction(() => document.body.dataset.offline === 'ready', null, { timeout: SAVE_TIMEOUT_MS });
    await screenshot(page, 'offline-reloaded');
  });

  it('served everything from the service worker and threw no page errors', () => {
    assert.ok(responsesWhileDown.length > 0);
    const fromNetwork = responsesWhileDown.filter((response) => !response.fromServiceWorker);
    assert.deepEqual(fromNetwork, [], 'responses that did not come from the service worker');
    for (const file of ['/web/main.js', '/web/core-worker.js', '/wasm/worker.js', '/dist/desia_light.wasm', '/examples/meshes/torus.obj']) {
      assert.ok(responsesWhileDown.some((response) => new URL(response.url).pathname === file), `${file} was served`);
    }
    assert.deepEqual(pageErrors, []);
  });
});

describe('playground offline never mixes versions', { timeout: 120_000 }, () => {
  let browser;
  let server;
  let context;
  const pageErrors = [];

  before(async () => {
    checkPrerequisites([FIRST_EXAMPLE, SHAPE_EXAMPLE]);
    browser = await openBrowser();
    ({ server, context } = browser);
  });

  after(async () => {
    await browser?.close();
  });

  it('offers no older snapshot to a newer page, and fails clearly offline instead', async () => {
    // The first page: its snapshot completes, so it works offline.
    const older = browser.page;
    older.on('pageerror', (error) => pageErrors.push(error.message));
    await older.goto(`${server.url}?example=${SHAPE_EXAMPLE}`);
    assert.equal((await waitForReady(older, SHAPE_EXAMPLE)).parts, '1');
    await older.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: SAVE_TIMEOUT_MS });
    assert.equal((await offlineIndicator(older)).state, 'ready');

    // A page loaded from the network after that snapshot (as after an update of the server),
    // whose own snapshot fails: one of its files is missing on the server.
    const newer = await context.newPage();
    newer.on('pageerror', (error) => pageErrors.push(error.message));
    await newer.addInitScript((missing) => {
      const post = ServiceWorker.prototype.postMessage;
      ServiceWorker.prototype.postMessage = function postWithMissingFile(message, transfer) {
        if (message?.type === 'snapshot') message = { ...message, urls: [...message.urls, new URL(missing, location.href).href] };
        return post.call(this, message, transfer);
      };
    }, MISSING_FILE);
    await newer.goto(`${server.url}?example=${SHAPE_EXAMPLE}`);
    assert.equal((await waitForReady(newer, SHAPE_EXAMPLE)).parts, '1');
    assert.equal(await newer.evaluate(() => navigator.serviceWorker.controller !== null), true, 'the service worker controls the page');
    await newer.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: SAVE_TIMEOUT_MS });
    const indicator = await offlineIndicator(newer);
    assert.equal(indicator.state, 'unavailable', `the older snapshot must not count for this page: ${JSON.stringify(indicator)}`);
    assert.equal(indicator.text, 'Online only');
    assert.ok(indicator.title.includes(MISSING_FILE), `the indicator says why: ${indicator.title}`);

    // Offline, the newer page's fresh worker gets nothing from the older snapshot: it fails.
    const servedToNewer = [];
    newer.on('response', (response) => servedToNewer.push({ url: response.url(), fromServiceWorker: response.fromServiceWorker() }));
    await context.setOffline(true);
    await restartWorkerWithCancel(newer);
    await newer.waitForFunction(() => /worker/i.test(document.querySelector('#error').textContent) && !document.querySelector('#error').hidden, null, { timeout: 30_000 });
    assert.notEqual(await newer.evaluate(() => document.body.dataset.core), 'ready', 'no worker ran on older files');
    await screenshot(newer, 'offline-no-mix');
    assert.deepEqual(servedToNewer.filter((response) => response.fromServiceWorker), [], 'cached files handed to the newer page');

    // The older page belongs to the snapshot: offline, its fresh worker loads the core from it.
    await restartWorkerWithCancel(older);
    await older.waitForFunction(() => document.body.dataset.design === 'cancelled' && document.body.dataset.core === 'ready', null, { timeout: 30_000 });
    await older.selectOption('#example-select', FIRST_EXAMPLE);
    assertInterlockingWithKey(await waitForReady(older, FIRST_EXAMPLE), 1);
    assert.deepEqual(pageErrors, []);
  });
});
