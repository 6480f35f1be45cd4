// SPDX-License-Identifier: GPL-3.0-or-later
//
// The npm package in a page: `npm pack`, install the tarball into an empty folder (no network),
// serve that folder (plus a copy of three for the viewer, through an import map) and, in headless
// Chromium, import 'desia' from the installed copy: a check and a seeded design equal to the
// native CLI's, computed in the package's module worker (the page keeps running meanwhile), a
// long design aborted with an AbortController, the next one fine, bad input as a DesiaError, and
// the drop-in viewer from 'desia/viewer' drawing a puzzle. Nothing leaves the origin.
//
//   node --test tests/browser/package.test.mjs
//
// Needs the WebAssembly build (dist/), the native CLI (build/native) and Chromium.
// Screenshots go to test-artifacts/package-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startServer } from '../../scripts/serve.mjs';
import { ARTIFACTS_DIR, REPO_ROOT, checkPrerequisites, openBrowser } from './support.mjs';

const CLI = path.join(REPO_ROOT, 'build/native/core/cli/desia');
const REFERENCE = path.join(REPO_ROOT, 'tests/reference/desia/data');
const K9_FILE = path.join(REFERENCE, 'result_puz/Cube_4x4x4_K9.puz');
const CUBE_FILE = path.join(REFERENCE, 'input_puz/Cube_4x4x4_origin.puz');
const BUNNY_FILE = path.join(REFERENCE, 'input_puz/bunny_origin.puz');
/** The viewer's background (web/view.js): pixels far from it belong to the drawing. */
const BACKGROUND = [0x1b, 0x1e, 0x24];

function run(command, args, { cwd = REPO_ROOT, env = {}, allowStatus = [0] } = {}) {
  const result = spawnSync(command, args, { cwd, encoding: 'utf8', maxBuffer: 64 << 20, env: { ...process.env, ...env } });
  if (result.error) throw result.error;
  assert.ok(allowStatus.includes(result.status), `${command} ${args.join(' ')} failed:\n${result.stdout}\n${result.stderr}`);
  return result;
}

/** The native CLI's design of `shapeFile`, as .puz text. */
function cliDesign(tmp, shapeFile, parts, seed) {
  const output = path.join(tmp, `design-${parts}-${seed}.puz`);
  run(CLI, ['design', 'voxel', '--input', shapeFile, '--parts', String(parts), '--seed', String(seed), '--jobs', '1', '--output', output]);
  return fs.readFileSync(output, 'utf8');
}

/**
 * A site with the package installed from its tarball, a copy of the three files the viewer
 * needs, the test page and a puzzle for <desia-viewer src>.
 */
function buildSite(tmp) {
  const npmEnv = { npm_config_cache: path.join(tmp, 'npm-cache'), npm_config_update_notifier: 'false' };
  const [packed] = JSON.parse(run('npm', ['pack', '--json', '--pack-destination', tmp], { env: npmEnv }).stdout);
  const site = path.join(tmp, 'site');
  fs.mkdirSync(site);
  fs.writeFileSync(path.join(site, 'package.json'), JSON.stringify({ name: 'desia-page-smoke', private: true }));
  run('npm', ['install', '--offline', '--no-audit', '--no-fund', path.join(tmp, packed.filename)], { cwd: site, env: npmEnv });
  const three = path.join(REPO_ROOT, 'node_modules/three');
  for (const file of ['build/three.module.js', 'build/three.core.js', 'examples/jsm/controls/OrbitControls.js']) {
    fs.mkdirSync(path.dirname(path.join(site, 'vendor/three', file)), { recursive: true });
    fs.copyFileSync(path.join(three, file), path.join(site, 'vendor/three', file));
  }
  fs.mkdirSync(path.join(site, 'puzzles'));
  fs.copyFileSync(K9_FILE, path.join(site, 'puzzles/Cube_4x4x4_K9.puz'));
  fs.writeFileSync(path.join(site, 'page.html'), `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <title>desia package smoke test</title>
  <link rel="icon" href="data:,">
  <script type="importmap">
    {
      "imports": {
        "desia": "/node_modules/desia/wasm/index.js",
        "desia/viewer": "/node_modules/desia/web/viewer.js",
        "three": "/vendor/three/build/three.module.js",
        "three/addons/": "/vendor/three/examples/jsm/"
      }
    }
  </script>
  <script type="module">
    import * as desiaPackage from 'desia';
    import * as viewerModule from 'desia/viewer';
    window.desiaPackage = desiaPackage;
    window.viewerModule = viewerModule;
    document.body.dataset.loaded = 'yes';
  </script>
</head>
<body>
  <div id="mounted" style="width: 480px; height: 360px"></div>
  <desia-viewer id="element" src="puzzles/Cube_4x4x4_K9.puz" style="width: 480px"></desia-viewer>
</body>
</html>
`);
  return { site, files: packed.files.map((file) => file.path) };
}

/** Share of a screenshot's pixels that are clearly coloured (parts), decoded by the browser. */
async function colouredShare(context, png) {
  const probe = await context.newPage();
  try {
    return await probe.evaluate(async ({ base64, background }) => {
      const image = new Image();
      image.src = `data:image/png;base64,${base64}`;
      await image.decode();
      const canvas = new OffscreenCanvas(image.width, image.height);
      const context2d = canvas.getContext('2d');
      context2d.drawImage(image, 0, 0);
      const { data } = context2d.getImageData(0, 0, image.width, image.height);
      let coloured = 0;
      for (let i = 0; i < data.length; i += 4) {
        const distance = Math.abs(data[i] - background[0]) + Math.abs(data[i + 1] - background[1]) + Math.abs(data[i + 2] - background[2]);
        const saturation = Math.max(data[i], data[i + 1], data[i + 2]) - Math.min(data[i], data[i + 1], data[i + 2]);
        if (distance > 60 && saturation > 30) coloured += 1;
      }
      return coloured / (data.length / 4);
    }, { base64: png.toString('base64'), background: BACKGROUND });
  } finally {
    await probe.close();
  }
}

describe('the npm package installed from its tarball, in a page', { timeout: 180_000 }, () => {
  let tmp;
  let browser;
  let siteServer;
  let page;
  const requestedUrls = [];
  const pageErrors = [];
  const texts = {};

  before(async () => {
    checkPrerequisites();
    assert.ok(fs.existsSync(CLI), 'the native CLI is missing: run bash scripts/build.sh native');
    tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-browser-package-'));
    const { site, files } = buildSite(tmp);
    assert.ok(files.includes('dist/desia_wasm.wasm'), 'the packed tarball lacks the WebAssembly module');
    assert.ok(fs.existsSync(path.join(site, 'node_modules/desia/dist/desia_wasm.wasm')), 'the installed package lacks the WebAssembly module');
    for (const [name, file] of [['k9', K9_FILE], ['cube', CUBE_FILE], ['bunny', BUNNY_FILE]]) texts[name] = fs.readFileSync(file, 'utf8');
    siteServer = await startServer({ port: 0, root: site });
    browser = await openBrowser();
    page = browser.page;
    browser.context.on('request', (request) => requestedUrls.push(request.url()));
    page.on('pageerror', (error) => pageErrors.push(error.message));
    await page.goto(`http://127.0.0.1:${siteServer.port}/page.html`);
    await page.waitForFunction(() => document.body.dataset.loaded === 'yes', null, { timeout: 30_000 });
    await page.evaluate(async () => {
      window.desia = await window.desiaPackage.createDesia();
    });
  });

  after(async () => {
    await browser?.close();
    await siteServer?.close();
    if (tmp) fs.rmSync(tmp, { recursive: true, force: true });
  });

  it('checks and designs in its module worker, with the native results, while the page keeps running', async () => {
    const out = await page.evaluate(async ({ k9, bunny }) => {
      const { desia } = window;
      const report = await desia.check(k9, { source: 'Cube_4x4x4_K9.puz' });
      // The design runs in the worker: the page's timers keep firing meanwhile.
      let ticks = 0;
      const timer = setInterval(() => { ticks += 1; }, 10);
      const progress = [];
      const started = performance.now();
      // N = 80 (about 1.7 s in WebAssembly): long enough to count the page's timer ticks meanwhile
      // (N = 20 takes about 0.15 s since issue 10's speed-ups).
      const design = await desia.designVoxel(bunny, { parts: 80, seed: 2, onProgress: (p) => progress.push(p) });
      const elapsedMs = performance.now() - started;
      clearInterval(timer);
      let error = null;
      try {
        await desia.check('4 4 4\n1 1 1 1\n1 1\n', { source: 'ragged.puz' });
      } catch (caught) {
        error = { isDesiaError: caught instanceof window.desiaPackage.DesiaError, code: caught.code, message: caught.message };
      }
      return { version: desia.version(), report, status: design.status, puz: design.puz, labelsArray: Array.isArray(design.document.voxel.labels),
        progressCount: progress.length, lastBestDepth: progress.at(-1)?.bestDepth, elapsedMs, ticks, error };
    }, texts);
    assert.match(out.version, /^\d+\.\d+\.\d+$/);
    assert.deepEqual(out.report, JSON.parse(run(CLI, ['check', K9_FILE, '--json']).stdout.replaceAll(K9_FILE, 'Cube_4x4x4_K9.puz')));
    assert.equal(out.status, 'success');
    assert.equal(out.puz, cliDesign(tmp, BUNNY_FILE, 80, 2));
    assert.equal(out.labelsArray, true);
    assert.ok(out.progressCount >= 1);
    assert.equal(out.lastBestDepth, 80);
    assert.ok(out.ticks >= Math.min(5, out.elapsedMs / 40), `only ${out.ticks} timer ticks in ${out.elapsedMs} ms: the page was blocked`);
    assert.deepEqual(out.error, { isDesiaError: true, code: 'bad-input', message: 'ragged.puz:3: row 2 of layer 1 has 2 values, expected Nx = 4' });
  });

  it('aborts a long design at once with an AbortController; the next design works', async () => {
    const out = await page.evaluate(async ({ bunny, cube }) => {
      const { desia } = window;
      const controller = new AbortController();
      let running;
      const started = new Promise((resolve) => { running = resolve; });
      const design = desia.designVoxel(bunny, { parts: 80, seed: 3, timeLimit: 300, signal: controller.signal, onProgress: () => running() });
      await started;
      const abortedAt = performance.now();
      controller.abort();
      let rejection = null;
      try {
        await design;
      } catch (error) {
        rejection = { name: error.name, isDomException: error instanceof DOMException, afterMs: performance.now() - abortedAt };
      }
      const already = await desia.check(cube, { signal: AbortSignal.abort() }).then(() => 'resolved', (error) => error.name);
      const next = await desia.designVoxel(cube, { parts: 7, seed: 3 });
      return { rejection, already, nextStatus: next.status, nextPuz: next.puz };
    }, texts);
    assert.ok(out.rejection, 'the aborted design resolved');
    assert.equal(out.rejection.name, 'AbortError');
    assert.equal(out.rejection.isDomException, true);
    assert.ok(out.rejection.afterMs < 1000, `rejected ${out.rejection.afterMs} ms after abort()`);
    assert.equal(out.already, 'AbortError');
    assert.equal(out.nextStatus, 'success');
    assert.equal(out.nextPuz, cliDesign(tmp, CUBE_FILE, 7, 3));
  });

  it("mounts the installed package's viewer and draws the puzzle", async () => {
    await page.evaluate(({ k9 }) => {
      window.mounted = window.viewerModule.mountViewer(document.querySelector('#mounted'), { text: k9, name: 'Cube_4x4x4_K9.puz' });
    }, texts);
    for (const id of ['mounted', 'element']) {
      await page.waitForFunction((hostId) => ['ready', 'error'].includes(document.getElementById(hostId).dataset.state), id, { timeout: 30_000 });
      const state = await page.evaluate((hostId) => {
        const host = document.getElementById(hostId);
        const canvas = host.shadowRoot?.querySelector('canvas');
        const message = host.shadowRoot?.querySelector('.message');
        return { state: host.dataset.state, message: message && !message.hidden ? message.textContent : '',
          canvas: canvas ? [canvas.width, canvas.height] : null, parts: host.shadowRoot?.querySelector('.viewport')?.dataset.parts ?? '' };
      }, id);
      assert.equal(state.state, 'ready', `${id}: ${state.message}`);
      assert.ok(state.canvas && state.canvas[0] > 0 && state.canvas[1] > 0, `${id}: a canvas with a size`);
      assert.equal(state.parts, '9');
      fs.mkdirSync(ARTIFACTS_DIR, { recursive: true });
      const png = await page.locator(`#${id}`).screenshot({ path: path.join(ARTIFACTS_DIR, `package-viewer-${id}.png`) });
      const share = await colouredShare(browser.context, png);
      assert.ok(share > 0.04, `${id}: only ${(share * 100).toFixed(1)}% of the viewer shows parts`);
    }
  });

  it("updates the viewer with a document alone: the viewer's core supplies its part surfaces", async () => {
    const out = await page.evaluate(async ({ bunny }) => {
      const [document_, report, surfaces] = await Promise.all([
        window.desia.parseDocument(bunny, { source: 'bunny.puz' }),
        window.desia.check(bunny, { source: 'bunny.puz' }),
        window.desia.partSurfaces(bunny, { source: 'bunny.puz' }),
      ]);
      await window.mounted.update(document_, report, 'bunny.puz');
      const host = document.getElementById('mounted');
      return { state: host.dataset.state, parts: host.shadowRoot.querySelector('.viewport').dataset.parts,
        documentParts: document_.parts.length, surfaceParts: surfaces.map((surface) => surface.partId),
        floats: surfaces.every((surface) => surface.positions instanceof Float32Array && surface.positions.length % 9 === 0) };
    }, texts);
    assert.equal(out.state, 'ready');
    assert.equal(out.parts, String(out.documentParts), 'one mesh per part');
    assert.deepEqual(out.surfaceParts, Array.from({ length: out.documentParts }, (_, k) => k + 1));
    assert.equal(out.floats, true);
  });

  it('asked nothing from other origins and threw no page errors', () => {
    const origin = `http://127.0.0.1:${siteServer.port}`;
    const elsewhere = requestedUrls.filter((url) => !url.startsWith(`${origin}/`) && !/^(data|blob):/.test(url));
    assert.deepEqual(elsewhere, []);
    assert.ok(requestedUrls.includes(`${origin}/node_modules/desia/wasm/worker.js`), 'the package worker was loaded');
    // The light module (voxels) or the full one (plates, frames): docs/architecture.md.
    assert.ok(requestedUrls.includes(`${origin}/node_modules/desia/dist/desia_light.wasm`)
      || requestedUrls.includes(`${origin}/node_modules/desia/dist/desia_wasm.wasm`), 'the core was loaded from the package');
    assert.deepEqual(pageErrors, []);
  });
});
