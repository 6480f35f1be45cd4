// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design and blocking graphs at scale (issue 11), in headless Chromium at 1400x900 and
// 390x844: while the worker designs the bunny with N = 80, the 3D view shows the deepest node so
// far, its placed parts growing before the result arrives, and the progress says how hard the
// request is; a plate design draws the bookcase as its plates are placed (123 plates, those not
// yet placed see-through). The blocking graphs of the 80-part bunny zoom and pan (the
// drawing's transform changes, by wheel, drag, buttons and keys), Find part 17 highlights and
// centres its node, and the matrix view draws N x N cells. Live design leaves the page
// responsive (issue 28, item 8): the bunny with N = 140 on two workers, measured over 5 s
// (tests/browser/live-frames.mjs; the real numbers are in docs/benchmarks.md, "Live design"), and
// a plate or frame design's live pictures are a few draw calls (the bookcase, the 882-beam scaffold).
//
//   node --test tests/browser/live.test.mjs
//
// Needs the same as playground.test.mjs. Screenshots go to test-artifacts/live-*-<width>.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  checkPrerequisites, openBrowser, screenshot, showDesignSettings, waitForReady,
} from './support.mjs';
import { measureLiveDesign } from './live-frames.mjs';

const BUNNY_SHAPE = 'bunny_origin.puz';
const BUNNY_PUZZLE = 'bunny_15x14x11_K80.puz';
const DESIGN_TIMEOUT_MS = 90_000;

/**
 * Samples, every 50 ms until the run the caller started ends, the parts of the deepest node the
 * view shows (#design-progress-box[data-live-parts]) and the meshes in the view.
 */
function watchLiveParts(page) {
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
        hint: document.querySelector('#design-progress-difficulty')?.textContent ?? '',
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

    // N = 80: since issue 10 made the designer faster, N = 60 takes under a second in WebAssembly,
    // too short for the view to show several depths at its at most four snapshots a second.
    it('shows the deepest node growing while the bunny is designed with N = 80', async () => {
      await page.goto(`${server.url}?example=${BUNNY_SHAPE}&parts=80&seed=1`);
      await showDesignSettings(page); // folded on a phone
      await waitForReady(page, BUNNY_SHAPE);
      await page.fill('#design-workers', '1');
      let shot = false;
      page.on('console', () => {});
      // The click sets body[data-design] to running before it returns (design-panel.js begin).
      await page.click('#design-button');
      const watching = watchLiveParts(page);
      // A picture mid-design: some parts placed, the remainder see-through. Taken at the first
      // live picture, not at a depth: on the loaded clean-clone CI the view showed only two
      // depths (under 20 parts) before the result, and waiting for 20 then timed out.
      const liveOrEnded = await page.waitForFunction(() => {
        if (document.body.dataset.design !== 'running') return 'ended';
        return Number(document.querySelector('#design-progress-box').dataset.liveParts || 0) >= 1 ? 'live' : false;
      }, null, { timeout: DESIGN_TIMEOUT_MS, polling: 20 });
      if (await liveOrEnded.jsonValue() === 'live') {
        await screenshot(page, `live-bunny-designing-${size}`);
        shot = true;
      }
      const samples = await watching;
      const running = samples.filter((sample) => sample.outcome === 'running' && sample.live !== null);
      const distinct = [...new Set(running.map((sample) => sample.live))];
      // At least two depths, growing: at most four snapshots a second, and a loaded machine (the
      // clean-clone CI beside other builds) saw only 4 and 17 before the 80 parts were done.
      assert.ok(distinct.length >= 2, `the view showed several depths before the result: ${distinct.join(', ')}`);
      for (let k = 1; k < distinct.length; k += 1) assert.ok(distinct[k] > distinct[k - 1], `growing: ${distinct.join(', ')}`);
      // The view draws the placed parts and the remainder, which is ghosted.
      const drawn = running.at(-1);
      assert.equal(drawn.meshes, drawn.live + 1, JSON.stringify(drawn));
      assert.equal(drawn.ghost, String(drawn.live + 1));
      // How hard the request is: 966 voxels in 80 parts.
      assert.match(running.at(-1).hint, /^~12 voxels per part: usually succeeds/);
      const last = samples.at(-1);
      assert.equal(last.outcome, 'success', JSON.stringify(last));
      assert.equal(last.meshes, 80, 'the result replaces the live view');
      assert.equal(last.ghost, '', 'nothing ghosted in the result');
      assert.ok(shot, 'a screenshot was taken mid-design');
      await screenshot(page, `live-bunny-designed-${size}`);
      assert.deepEqual(pageErrors, []);
    });

    // Before issue 28's item 8: 3.4-3.6 frames a second, the main thread blocked 6.2-8.2 s of
    // 5.3-6.2 s (long tasks overlap the frames), the longest task 1.0-1.4 s, a redraw (new
    // materials, so their shader programs compiled again) at every snapshot. Now 39-52 frames a
    // second with the machine's load at 7-15, no program compiled during the design. The bounds
    // are lenient: software WebGL on a loaded 2-core machine, where the two searches take both cores.
    it('keeps drawing frames while the bunny is designed with N = 140 on two workers', async () => {
      await page.goto(`${server.url}?example=${BUNNY_SHAPE}&parts=140&seed=1`);
      await showDesignSettings(page);
      await waitForReady(page, BUNNY_SHAPE);
      await page.fill('#design-workers', '2');
      const measured = await measureLiveDesign(page, { seconds: 5 });
      await screenshot(page, `live-bunny-140-${size}`);
      await page.click('#design-cancel');
      await page.waitForFunction(() => document.body.dataset.design !== 'running');
      const numbers = JSON.stringify(measured);
      assert.equal(measured.outcome, 'running', `N = 140 takes longer than the window: ${numbers}`);
      assert.ok(measured.liveDepths.length >= 2 && measured.renders >= 2, `the view drew the deepest node as it grew: ${numbers}`);
      // Materials are reused and live design's programs compiled ahead: none more with every update.
      assert.ok(measured.programsAfter - measured.programsBefore <= 4, `shader programs: ${numbers}`);
      assert.ok(measured.fps >= 15, `frames a second: ${numbers}`);
      assert.ok(measured.blockedMs <= 0.6 * measured.seconds * 1000, `main thread blocked: ${numbers}`);
      assert.deepEqual(pageErrors, []);
    });

    it('draws the 123-plate bookcase as its plates are placed', async () => {
      await page.selectOption('#example-select', 'bookcase_123.json');
      await waitForReady(page, 'bookcase_123.json');
      await page.click('#design-button');
      const samples = await watchLiveParts(page);
      const running = samples.filter((sample) => sample.outcome === 'running' && sample.live !== null);
      const distinct = [...new Set(running.map((sample) => sample.live))];
      assert.ok(distinct.length >= 3, `the view showed several depths before the plan: ${distinct.join(', ')}`);
      for (let k = 1; k < distinct.length; k += 1) assert.ok(distinct[k] > distinct[k - 1], `growing: ${distinct.join(', ')}`);
      // The input's 123 plates stay on screen: those not yet placed are see-through.
      const drawn = running.at(-1);
      assert.equal(drawn.meshes, 123);
      assert.equal(drawn.ghost.split(' ').filter(Boolean).length, 123 - drawn.live, JSON.stringify({ ...drawn, ghost: '…' }));
      const last = samples.at(-1);
      assert.equal(last.outcome, 'success', last.text);
      assert.equal(last.ghost, '');
      await screenshot(page, `live-bookcase-planned-${size}`);
    });

    // Plates and frames (issue 28, item 8): a live picture recoloured every part's own mesh, so
    // each frame drew every plate or beam and its outline (the bookcase 247 draw calls, the
    // 882-beam scaffold 1,767: 20 frames a second, the main thread blocked 7.7 s of 10 s). Now the
    // input's surfaces are merged as a voxel node's are: a few draw calls whatever the size.
    for (const example of ['bookcase_123.json', 'scaffold_882.json']) {
      it(`draws ${example}'s live design as a few merged meshes`, async () => {
        await page.goto(`${server.url}?example=${example}`);
        await waitForReady(page, example);
        const measured = await measureLiveDesign(page, { seconds: 5 });
        await screenshot(page, `live-${example.replace('.json', '')}-${size}`);
        await page.click('#design-cancel').catch(() => {});
        await page.waitForFunction(() => document.body.dataset.design !== 'running');
        const numbers = JSON.stringify(measured);
        assert.ok(measured.liveDepths.length >= 2 && measured.renders >= 2, `the view drew the plan as it grew: ${numbers}`);
        assert.ok(measured.maxLiveCalls > 0 && measured.maxLiveCalls <= 8, `draw calls of a live picture: ${numbers}`);
        assert.ok(measured.programsAfter - measured.programsBefore <= 4, `shader programs: ${numbers}`);
        assert.ok(measured.fps >= 15, `frames a second: ${numbers}`);
        assert.deepEqual(pageErrors, []);
      });
    }

    it('zooms, pans, finds part 17 and shows the 80-part bunny as an adjacency matrix', async () => {
      await page.selectOption('#example-select', BUNNY_PUZZLE);
      await waitForReady(page, BUNNY_PUZZLE);
      await page.evaluate(() => {
        document.querySelector('#graphs-details').open = true;
        window.dbgSelections = [];
        document.querySelector('#dbg-panel').addEventListener('dbg-select', (event) => window.dbgSelections.push(event.detail.partId));
      });
      const figures = () => page.evaluate(() => [...document.querySelectorAll('#dbg-panel figure.dbg-graph')].map((figure) => ({
        drawn: figure.dataset.drawn,
        nodes: figure.querySelectorAll('circle.dbg-node').length,
        edges: Number(figure.dataset.edges),
        transform: figure.querySelector('g.dbg-zoom')?.getAttribute('transform'),
        zoom: Number(figure.dataset.zoom),
      })));
      const before = await figures();
      assert.equal(before.length, 3);
      for (const figure of before) {
        assert.equal(figure.drawn, 'parts', 'up to 200 parts are drawn part by part');
        assert.equal(figure.nodes, 80);
        assert.equal(figure.transform, 'translate(0 0) scale(1)');
      }

      // The wheel zooms about the pointer.
      const first = page.locator('#dbg-panel figure.dbg-graph svg.dbg-svg').first();
      await first.scrollIntoViewIfNeeded();
      let box = await first.boundingBox();
      await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.3);
      await page.mouse.wheel(0, -400);
      await page.waitForFunction(() => document.querySelector('#dbg-panel figure.dbg-graph').dataset.zoom !== '1');
      const wheeled = (await figures())[0];
      assert.ok(wheeled.zoom > 1, `zoomed in: ${wheeled.transform}`);
      // A drag pans (and does not select a part or enlarge the figure).
      box = await first.boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width / 2 + 30, box.y + box.height / 2 + 20, { steps: 5 });
      await page.mouse.up();
      const dragged = (await figures())[0];
      assert.notEqual(dragged.transform, wheeled.transform, 'the drag panned');
      assert.equal(dragged.zoom, wheeled.zoom);
      assert.equal(await page.locator('#dbg-panel figure.dbg-wide').count(), 0, 'a drag does not enlarge');
      // Buttons for keyboard users: Zoom in on every graph, Fit back.
      await page.click('#dbg-panel button[aria-label="Zoom in"]');
      const buttoned = await figures();
      assert.ok(buttoned[1].zoom > 1 && buttoned[2].zoom > 1, 'every graph zoomed');
      await page.click('#dbg-panel button[aria-label="Show the whole graphs"]');
      for (const figure of await figures()) assert.equal(figure.transform, 'translate(0 0) scale(1)');
      // Keys on a focused drawing.
      await first.focus();
      await page.keyboard.press('+');
      await page.keyboard.press('ArrowRight');
      assert.notEqual((await figures())[0].transform, 'translate(0 0) scale(1)');

      // Find part 17: highlighted in every graph and in the middle of each drawing.
      await page.fill('#dbg-find', '17');
      await page.press('#dbg-find', 'Enter');
      const found = await page.evaluate(() => [...document.querySelectorAll('#dbg-panel figure.dbg-graph svg.dbg-svg')].map((root) => {
        const node = root.querySelector('circle.dbg-node[data-part="17"]').getBoundingClientRect();
        const frame = root.getBoundingClientRect();
        return {
          selected: root.querySelector('circle.dbg-node[data-part="17"]').dataset.selected,
          dx: (node.x + node.width / 2) - (frame.x + frame.width / 2),
          dy: (node.y + node.height / 2) - (frame.y + frame.height / 2),
          size: frame.width,
        };
      }));
      await screenshot(page, `live-dbg-find17-${size}`);
      for (const node of found) {
        assert.equal(node.selected, 'true');
        assert.ok(Math.abs(node.dx) < node.size * 0.05 && Math.abs(node.dy) < node.size * 0.05, `centred: ${JSON.stringify(node)}`);
      }
      assert.deepEqual(await page.evaluate(() => window.dbgSelections), [17], 'Find selects the part on the page too');
      await page.fill('#dbg-find', '999');
      await page.press('#dbg-find', 'Enter');
      assert.match(await page.textContent('#dbg-find-status'), /no part 999 \(parts 1–80\)/);

      // The matrix: 80 x 80 cells per direction, filled where the graph has an edge.
      await page.click('#dbg-panel button[data-view="matrix"]');
      const matrix = await page.evaluate(() => {
        const view = document.querySelector('#dbg-panel .dbg-matrix');
        return {
          size: Number(view.dataset.size), cells: view.querySelectorAll('rect.dbg-cell').length, direction: view.dataset.direction,
          filled: view.querySelectorAll('rect.dbg-cell[data-edge="true"]').length, edges: Number(view.dataset.edges),
          scrolls: view.querySelector('.dbg-matrix-scroll').scrollHeight > view.querySelector('.dbg-matrix-scroll').clientHeight,
          selection: view.querySelector('.dbg-matrix-selection').getAttribute('visibility'),
        };
      });
      await screenshot(page, `live-dbg-matrix-${size}`);
      assert.equal(matrix.size, 80);
      assert.equal(matrix.cells, 80 * 80);
      assert.equal(matrix.filled, before[0].edges, 'one filled cell per edge of G(+x)');
      assert.equal(matrix.selection, 'visible', 'part 17 stays selected: its row and column');
      assert.ok(matrix.scrolls, 'the matrix scrolls');
      await page.click('#dbg-panel .dbg-matrix-directions button:nth-child(2)');
      assert.equal(await page.getAttribute('#dbg-panel .dbg-matrix', 'data-direction'), before.length > 1 ? '+y' : '+x');
      await page.locator('#dbg-panel rect.dbg-cell[data-row="5"][data-col="9"]').click();
      assert.deepEqual(await page.evaluate(() => window.dbgSelections), [17, 5], 'a cell selects its row');
      // Back to the drawings for the next tests (the choice outlives a new report).
      await page.click('#dbg-panel button[data-view="drawing"]');
      assert.equal(await page.locator('#dbg-panel figure.dbg-graph').count(), 3);
      assert.deepEqual(pageErrors, []);
    });
  });
}
