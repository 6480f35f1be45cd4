// SPDX-License-Identifier: GPL-3.0-or-later
//
// Smoke test of the playground in headless Chromium: the page loads, its worker runs the
// WebAssembly core on the bundled examples, a broken file shows an error without breaking the
// page, and nothing is requested from outside 127.0.0.1.
//
//   node --test tests/browser/
//
// Needs Debian's /usr/bin/chromium, node_modules (three, playwright-core) and a WebAssembly build
// (bash scripts/build.sh wasm). Screenshots go to test-artifacts/.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import {
  REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, screenshot, waitForReady, waitForSettled,
} from './support.mjs';

const FIRST_EXAMPLE = 'Cube_4x4x4_K9.puz';
const BUNNY_EXAMPLE = 'bunny_15x14x11_K80.puz';
/** Every bundled example: part count and the key's free direction (shared/reference/README.md). */
const EXAMPLES = [
  { file: 'Cube_4x4x4_K9.puz', parts: 9, keyDirection: '-z' },
  { file: 'Cube_4x4x4_K9_01.puz', parts: 7, keyDirection: '+y' },
  { file: 'Cube_Hollow_4x4x4_K7.puz', parts: 7, keyDirection: '-z' },
  { file: 'cube_5x5x5_K16.puz', parts: 16, keyDirection: '+y' },
  { file: 'cartoon_dog.puz', parts: 14, keyDirection: '+y' },
  { file: 'bunny_15x14x11_K80.puz', parts: 80, keyDirection: '+y' },
];

/** Deterministic non-text bytes: what a user gets when picking the wrong file. */
function garbageBytes(length) {
  const bytes = Buffer.alloc(length);
  let state = 0x2545f491;
  for (let i = 0; i < length; i += 1) {
    state = (Math.imul(state, 1103515245) + 12345) >>> 0;
    bytes[i] = state >>> 24;
  }
  return bytes;
}

describe('playground in headless Chromium', { timeout: 60_000 }, () => {
  let browser;
  let server;
  let context;
  let page;
  const requestedUrls = [];
  const pageErrors = [];

  before(async () => {
    checkPrerequisites(EXAMPLES.map(({ file }) => file));
    browser = await openBrowser();
    ({ server, context, page } = browser);
    // Context-wide, so requests from the worker are seen as well as the page's.
    context.on('request', (request) => requestedUrls.push(request.url()));
    page.on('request', (request) => requestedUrls.push(request.url()));
    page.on('pageerror', (error) => pageErrors.push(error.message));
  });

  after(async () => {
    await browser?.close();
  });

  it('loads and reports the first example as interlocking with key 1', async () => {
    // The first visit opens a shape to design from (issue 28, item 3); this puzzle by its link.
    await page.goto(`${server.url}?example=${FIRST_EXAMPLE}`);
    const state = await waitForReady(page, FIRST_EXAMPLE);
    await screenshot(page, 'playground-first-example');
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '9');
    if (state.webgl === 'on') assert.equal(state.meshes, '9', 'one mesh per part');
    // Half-way through removing the second part of the order.
    await page.locator('#disassembly-range').fill('1.5');
    assert.match(await page.locator('#disassembly-step').textContent(), /^removing part \d+ \(2 of 8\)$/);
    await screenshot(page, 'playground-first-example-disassembly');
  });

  it('shows the 80-part bunny as interlocking', async () => {
    await page.selectOption('#example-select', BUNNY_EXAMPLE);
    const state = await waitForReady(page, BUNNY_EXAMPLE);
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '80');
    if (state.webgl === 'on') assert.equal(state.meshes, '80', 'one mesh per part');
    await screenshot(page, 'playground-bunny');
  });

  it('reports every bundled example as interlocking with key 1', async () => {
    for (const example of EXAMPLES) {
      await page.selectOption('#example-select', example.file);
      const state = await waitForReady(page, example.file);
      assertInterlockingWithKey(state, 1);
      assert.equal(state.parts, String(example.parts), `${example.file}: parts`);
      assert.equal(state.keyDirections, example.keyDirection, `${example.file}: key directions`);
    }
  });

  it('shows an error for a binary file and recovers', async () => {
    await page.setInputFiles('#file-input', {
      name: 'bad.puz',
      mimeType: 'application/octet-stream',
      buffer: garbageBytes(512),
    });
    const failed = await waitForSettled(page, 'bad.puz');
    await screenshot(page, 'playground-bad-file');
    assert.equal(failed.status, 'error', `expected an error, got verdict "${failed.verdict}"`);
    assert.match(failed.error, /^bad\.puz: not a text file/, 'the error names the file and its problem');

    await page.selectOption('#example-select', FIRST_EXAMPLE);
    const recovered = await waitForReady(page, FIRST_EXAMPLE);
    assertInterlockingWithKey(recovered, 1);
    assert.equal(recovered.error, '', 'the error box is cleared');
  });

  it("shows the core's message for a malformed .puz", async () => {
    await page.setInputFiles('#file-input', {
      name: 'broken.puz',
      mimeType: 'text/plain',
      buffer: Buffer.from('4 4 4\n1 2 3\n'),
    });
    const failed = await waitForSettled(page, 'broken.puz');
    assert.equal(failed.status, 'error', `expected an error, got verdict "${failed.verdict}"`);
    // The page passes the file name as `source`; the core names file and line and the problem.
    assert.match(failed.error, /^broken\.puz:\d+/, 'the error names the file and line');
    assert.ok(failed.error.replace(/^broken\.puz[:\d]*\s*/, '').length > 10, `the core's message is missing: "${failed.error}"`);

    await page.selectOption('#example-select', FIRST_EXAMPLE);
    assertInterlockingWithKey(await waitForReady(page, FIRST_EXAMPLE), 1);
  });

  it('gives verdicts or clear errors for the hostile inputs of issue 14 and stays usable', async () => {
    const folder = path.join(REPO_ROOT, 'tests/data/contacts');
    const inputs = readdirSync(folder).sort().map((name) => ({ name, buffer: readFileSync(path.join(folder, name)) }));
    const deep = `{"kind":"plate","parts":[{"id":1}],"contacts":[],"plates":${'['.repeat(100000)}${']'.repeat(100000)}}`;
    inputs.push({ name: 'deep.json', buffer: Buffer.from(deep) });
    await page.selectOption('#method-select', 'lp');
    try {
      for (const { name, buffer } of inputs) {
        await page.setInputFiles('#file-input', { name, mimeType: 'application/json', buffer });
        const state = await waitForSettled(page, name);
        if (name === 'deep.json') {
          assert.equal(state.status, 'error', `${name}: ${state.verdict}`);
          assert.match(state.error, /^deep\.json:1:\d+: plates\[0\]\[0\].*nested more than 256 levels deep/);
        } else {
          assert.equal(state.status, 'ready', `${name}: ${state.error}`);
          assert.equal(state.verdictCode, 'not-interlocking', `${name}: ${state.verdict}`);
        }
      }
      await screenshot(page, 'playground-hostile-input');
    } finally {
      await page.selectOption('#method-select', 'dbg');
    }
    await page.selectOption('#example-select', FIRST_EXAMPLE);
    assertInterlockingWithKey(await waitForReady(page, FIRST_EXAMPLE), 1);
  });

  it('reports a worker that cannot start and recovers once it can', async () => {
    const freshPage = await context.newPage();
    freshPage.on('pageerror', (error) => pageErrors.push(error.message));
    try {
      // The package's worker script fails to load (the page imports the package itself, so its
      // modules load): the worker dies before it can say anything.
      await freshPage.route('**/wasm/worker.js', (route) => route.abort());
      await freshPage.goto(`${server.url}?example=${FIRST_EXAMPLE}`);
      const failed = await waitForSettled(freshPage, FIRST_EXAMPLE);
      assert.equal(failed.status, 'error');
      assert.match(failed.error, /worker/i, 'the error says the worker failed');
      // Wait until the page stops restarting on its own, so no half-started worker is left over.
      await freshPage.waitForFunction(() => /in a row/.test(document.querySelector('#error').textContent));
      await screenshot(freshPage, 'playground-worker-failure');

      await freshPage.unroute('**/wasm/worker.js');
      await freshPage.selectOption('#example-select', BUNNY_EXAMPLE);
      assertInterlockingWithKey(await waitForReady(freshPage, BUNNY_EXAMPLE), 1);
    } finally {
      await freshPage.close();
    }
  });

  // Issue 28: the page's requests wait for the package's worker instead of being lost: the
  // worker script arrives 2 s late, long after the page asked for its first check.
  it('answers requests sent before the worker started', async () => {
    const freshPage = await context.newPage();
    freshPage.on('pageerror', (error) => pageErrors.push(error.message));
    try {
      await freshPage.route('**/wasm/worker.js', async (route) => {
        await new Promise((resolve) => { setTimeout(resolve, 2000); });
        await route.continue();
      });
      await freshPage.goto(`${server.url}?example=${FIRST_EXAMPLE}`);
      assert.equal(await freshPage.evaluate(() => document.body.dataset.core), 'starting', 'the page asked before the core was there');
      assertInterlockingWithKey(await waitForReady(freshPage, FIRST_EXAMPLE), 1);
      assert.equal(await freshPage.evaluate(() => document.body.dataset.core), 'ready');
    } finally {
      await freshPage.close();
    }
  });

  it('never requests anything outside 127.0.0.1 and throws no page errors', () => {
    const external = requestedUrls.filter((url) => {
      const { protocol, hostname } = new URL(url);
      return !['data:', 'blob:'].includes(protocol) && hostname !== '127.0.0.1';
    });
    assert.deepEqual(external, [], 'requests left the origin');
    // The light module first; the full one once a plate or frame came (docs/architecture.md).
    assert.ok(requestedUrls.some((url) => url.endsWith('/dist/desia_light.wasm')), 'the worker fetched the light module');
    assert.deepEqual(pageErrors, []);
  });
});
