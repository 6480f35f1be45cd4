// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part list and the playback aids (issue 11) in headless Chromium, at 1400x900 and 390x844,
// for a voxel puzzle (the 9-part cube), a plate plan (the TABLE designed with seed 1) and a
// frame (the designed FRAME CUBE):
// a part is selected from the list, from a click on it in the 3D view (the pointer put on the
// projected centre of a part that is in front there) and from its node in the blocking graphs,
// and the selection shows in all three; Isolate, Hide and Show all change the meshes drawn; the
// keyboard does the same (Enter, H, I, A, Escape); hovering names the part; Next and Previous
// move one part at a time, the leaving part's way out is drawn, and removed parts lie in the
// tray beside the assembly (outside its bounding box); long disassemblies play faster.
//
//   node --test tests/browser/parts.test.mjs
//
// Screenshots go to test-artifacts/parts-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import { REPO_ROOT, checkPrerequisites, openBrowser, screenshot, showDesignSettings, waitForReady } from './support.mjs';

const CUBE = 'Cube_4x4x4_K9.puz';
const BUNNY = 'bunny_15x14x11_K80.puz';
const TABLE = 'table.json';
const TABLE_PLAN = 'table_plan_seed1.json';
const FRAME_CUBE = 'frame_cube_result.json';
const DESIGN_TIMEOUT_MS = 30_000;

/** What the page says about parts: the list, the view, the graphs. */
function partsState(page) {
  return page.evaluate(() => {
    const list = document.querySelector('#part-list');
    const viewport = document.querySelector('#viewport');
    return {
      count: Number(list.dataset.count),
      selected: list.dataset.selected,
      hiddenList: list.dataset.hidden,
      ariaSelected: [...list.querySelectorAll('li[aria-selected="true"]')].map((item) => item.dataset.part),
      viewSelected: viewport.dataset.selected,
      visible: Number(viewport.dataset.visible),
      meshes: Number(viewport.dataset.parts),
      tray: Number(viewport.dataset.tray),
      arrow: viewport.dataset.arrow,
      step: Number(viewport.dataset.step),
      playing: document.querySelector('#viewer-controls').dataset.playing === 'true',
      graphSelected: [...document.querySelectorAll('#dbg-panel circle.dbg-node[data-selected="true"]')].map((node) => node.dataset.part),
      graphs: Number(document.querySelector('#dbg-panel').dataset.graphs),
    };
  });
}

/** A part whose centre, projected on the screen, shows that part (nothing in front of it there). */
async function pickablePart(page, except) {
  return page.evaluate((skip) => {
    const view = window.__desiaView;
    const list = [...document.querySelectorAll('#part-list li')].map((item) => Number(item.dataset.part));
    const canvas = document.querySelector('#viewport canvas').getBoundingClientRect();
    for (const partId of list) {
      if (partId === skip) continue;
      const point = view.screenPoint(partId);
      if (!point || point.x < canvas.left + 4 || point.y < canvas.top + 4 || point.x > canvas.right - 4) continue;
      // Keep clear of the playback controls drawn over the bottom of the view.
      const controls = document.querySelector('#viewer-controls').getBoundingClientRect();
      if (point.y > controls.top - 4 || point.y > canvas.bottom - 4) continue;
      if (view.partAt(point.x, point.y) === partId) return { partId, ...point };
    }
    return null;
  }, except);
}

/** Steps with the Next / Prev button and waits until the animation has stopped there. */
async function step(page, button, expected) {
  await page.click(button);
  await page.waitForFunction((target) => Number(document.querySelector('#viewport').dataset.step) === target
    && document.querySelector('#viewer-controls').dataset.playing === 'false', expected, { timeout: 10_000 });
  return partsState(page);
}

/** True when the two boxes ({ min, max }) do not overlap (touching counts as apart). */
function apart(a, b) {
  return [0, 1, 2].some((axis) => a.max[axis] <= b.min[axis] + 1e-6 || b.max[axis] <= a.min[axis] + 1e-6);
}

/** Selection, hiding and the keyboard: the same for every kind of assembly. */
async function checkSelection(page, { size, name, total, listed, graphPart }) {
  let state = await partsState(page);
  assert.equal(state.count, total);
  assert.equal(state.meshes, total);
  assert.equal(state.visible, total);
  const entries = await page.$$eval('#part-list li', (items) => items.map((item) => [...item.children].map((child) => child.textContent).filter(Boolean).join(' | ')));
  assert.deepEqual(entries.slice(0, listed.length), listed);

  // From the list.
  await page.click('#part-list li[data-part="3"]');
  state = await partsState(page);
  assert.deepEqual([state.selected, state.viewSelected, state.ariaSelected], ['3', '3', ['3']]);
  assert.deepEqual(state.graphSelected, Array(state.graphs).fill('3'), 'part 3 is marked in every graph');

  // From the 3D view: a click on a part in front (not a drag) selects it. (On a phone the list
  // is under the view: scroll back up to it first.)
  await page.locator('#viewport canvas').scrollIntoViewIfNeeded();
  const target = await pickablePart(page, 3);
  assert.ok(target, 'some part is in front at its own centre');
  await page.mouse.click(target.x, target.y);
  state = await partsState(page);
  assert.equal(state.selected, String(target.partId), 'the clicked part is selected');
  assert.equal(state.viewSelected, String(target.partId));
  // Hovering names it.
  await page.mouse.move(target.x + 1, target.y);
  await page.mouse.move(target.x, target.y);
  const label = page.locator('#viewport .hover-label');
  await label.waitFor({ state: 'visible' });
  assert.match(await label.textContent(), new RegExp(`^${name} ${target.partId}\\b`));
  await screenshot(page, `parts-${size}-${name}-selected`);

  // From a blocking graph.
  // (Its number is drawn over the node and takes the click, as it does for a user.)
  await page.locator(`#dbg-panel figure.dbg-graph .dbg-node-group:has(circle.dbg-node[data-part="${graphPart}"])`).first().click();
  state = await partsState(page);
  assert.deepEqual([state.selected, state.viewSelected], [String(graphPart), String(graphPart)]);
  assert.ok(!(await page.locator('#dbg-panel figure.dbg-wide').count()), 'a click on a node selects, it does not zoom');

  // Isolate, Show all, Hide.
  await page.click('#part-isolate');
  state = await partsState(page);
  assert.equal(state.visible, 1, 'only the isolated part is drawn');
  await screenshot(page, `parts-${size}-${name}-isolated`);
  await page.click('#part-show-all');
  assert.equal((await partsState(page)).visible, total);
  await page.click('#part-hide');
  state = await partsState(page);
  assert.equal(state.visible, total - 1);
  assert.equal(state.hiddenList, String(graphPart));
  await page.click('#part-show-all');

  // The keyboard: Enter selects, H hides, I isolates, A shows all, Escape clears.
  await page.focus('#part-list li[data-part="2"]');
  await page.keyboard.press('Enter');
  assert.equal((await partsState(page)).selected, '2');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('h');
  state = await partsState(page);
  assert.deepEqual([state.selected, state.hiddenList, state.visible], ['3', '3', total - 1]);
  await page.keyboard.press('i');
  assert.equal((await partsState(page)).visible, 1);
  await page.keyboard.press('a');
  assert.equal((await partsState(page)).visible, total);
  await page.keyboard.press('Escape');
  state = await partsState(page);
  assert.deepEqual([state.selected, state.viewSelected, state.graphSelected], ['', '', []]);
}

/** Next, Previous, the arrow and the tray. */
async function checkPlayback(page, { size, name, order }) {
  await page.locator('#disassembly-range').fill('0');
  let state = await step(page, '#disassembly-next', 1);
  assert.equal(state.tray, 1, 'the first removed part lies in the tray');
  const positions = await page.evaluate(() => ({
    inAssembly: window.__desiaView.partPositions(),
    tray: window.__desiaView.trayPositions(),
    bounds: window.__desiaView.assemblyBounds(),
  }));
  assert.deepEqual(Object.keys(positions.tray), [String(order[0])]);
  assert.equal(positions.inAssembly[order[0]], undefined);
  const first = await page.evaluate((partId) => window.__desiaView.partBounds(partId), order[0]);
  assert.ok(apart(first, positions.bounds), `part ${order[0]} in the tray ${JSON.stringify(first)} is off the assembly ${JSON.stringify(positions.bounds)}`);
  assert.equal(state.visible, state.meshes, 'a removed part stays in the picture');
  assert.equal(state.arrow, String(order[1]), 'the next part to leave shows its way out');

  state = await step(page, '#disassembly-next', 2);
  assert.equal(state.tray, 2);
  await screenshot(page, `parts-${size}-${name}-tray`);
  const trayed = await page.evaluate(() => window.__desiaView.trayPositions());
  assert.deepEqual(Object.keys(trayed).map(Number).sort((a, b) => a - b), [order[0], order[1]].sort((a, b) => a - b));
  const second = await page.evaluate((partId) => window.__desiaView.partBounds(partId), order[1]);
  assert.ok(apart(second, positions.bounds) && apart(first, second), 'tray places do not overlap the assembly or each other');

  state = await step(page, '#disassembly-prev', 1);
  assert.equal(state.tray, 1, 'Previous puts the last removed part back');
  assert.ok((await page.evaluate(() => window.__desiaView.partPositions()))[order[1]], `part ${order[1]} is back in the assembly`);
  state = await step(page, '#disassembly-prev', 0);
  assert.equal(state.tray, 0);
  assert.equal(await page.isDisabled('#disassembly-prev'), true, 'nothing before assembled');
  assert.equal(state.arrow, '', 'no arrow while assembled');

  // Half-way through a removal the arrow is drawn for the moving part.
  await page.locator('#disassembly-range').fill('0.3');
  assert.equal((await partsState(page)).arrow, String(order[0]));
  await screenshot(page, `parts-${size}-${name}-arrow`);
  await page.locator('#disassembly-range').fill('0');
}

for (const viewport of [{ width: 1400, height: 900 }, { width: 390, height: 844 }]) {
  const size = `${viewport.width}x${viewport.height}`;
  describe(`part list and playback at ${size}`, { timeout: 180_000 }, () => {
    let browser;
    let page;
    const pageErrors = [];

    before(async () => {
      checkPrerequisites([CUBE, BUNNY]);
      browser = await openBrowser({ viewport });
      page = browser.page;
      page.on('pageerror', (error) => pageErrors.push(error.message));
    });

    after(async () => {
      await browser?.close();
    });

    it('selects, hides, isolates and steps through the 9-part cube', async (t) => {
      await page.goto(`${browser.server.url}?example=${CUBE}`);
      await showDesignSettings(page); // folded on a phone
      const state = await waitForReady(page, CUBE);
      if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
      assert.deepEqual(await page.$eval('#part-list li[data-part="1"] .part-swatch', (swatch) => getComputedStyle(swatch).backgroundColor), 'rgb(255, 194, 26)', 'the key is gold');
      await checkSelection(page, { size, name: 'part', total: 9, listed: ['part 1 (key) | 7 voxels'], graphPart: 5 });
      const order = (await page.textContent('#order')).split(/[^0-9]+/).filter(Boolean).map(Number);
      await checkPlayback(page, { size, name: 'part', order });
      // The list scrolls inside itself and is on screen beside (wide) or below (narrow) the view.
      const layout = await page.evaluate(() => {
        const list = document.querySelector('#part-list').getBoundingClientRect();
        const view = document.querySelector('#viewport').getBoundingClientRect();
        return { listLeft: list.left, listTop: list.top, viewRight: view.right, viewBottom: view.bottom, listWidth: list.width, pageWidth: document.documentElement.scrollWidth };
      });
      if (viewport.width >= 1000) assert.ok(layout.listLeft >= layout.viewRight - 1, `the list is beside the view: ${JSON.stringify(layout)}`);
      else assert.ok(layout.listTop >= layout.viewBottom - 1 && layout.listWidth > 300, `the list is under the view, as wide as the page: ${JSON.stringify(layout)}`);
      assert.ok(layout.pageWidth <= viewport.width, 'nothing sticks out sideways');
      await page.locator('#parts-details').screenshot({ path: `test-artifacts/parts-${size}-list.png` });
      assert.deepEqual(pageErrors, []);
    });

    it('selects, hides, isolates and steps through the TABLE plan', async (t) => {
      await page.selectOption('#example-select', TABLE);
      let state = await waitForReady(page, TABLE);
      if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
      await page.fill('#design-form [name="seed"]', '1');
      await page.click('#design-button');
      await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: DESIGN_TIMEOUT_MS });
      state = await waitForReady(page, TABLE_PLAN);
      await checkSelection(page, { size, name: 'plate', total: 6, listed: ['plate 1 (key) | top', 'plate 2 | left side'], graphPart: 4 });
      await checkPlayback(page, { size, name: 'plate', order: [1, 2, 3, 4, 5, 6] });
      assert.deepEqual(pageErrors, []);
    });

    it('selects, hides, isolates and steps through the designed FRAME CUBE', async (t) => {
      await page.selectOption('#example-select', FRAME_CUBE);
      const state = await waitForReady(page, FRAME_CUBE);
      if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
      await checkSelection(page, { size, name: 'beam', total: 12, listed: ['beam 1 (key) | input beam 12', 'beam 2 | input beam 11'], graphPart: 4 });
      const order = (await page.textContent('#order')).split(/[^0-9]+/).filter(Boolean).map(Number);
      await checkPlayback(page, { size, name: 'beam', order });
      assert.deepEqual(pageErrors, []);
    });

    if (viewport.width >= 1000) {
      it('plays the 80-part bunny in 20 s at 1x, not 79 (or 82 moves)', async (t) => {
        await page.selectOption('#example-select', BUNNY);
        const state = await waitForReady(page, BUNNY);
        if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
        // The core's plan of moves (82) is shorter than its removal paths (85 moves): the bunny
        // plays move by move (docs/playground.md), each part going out alone into the tray.
        const core = await loadDesiaModule();
        const plan = core.check(readFileSync(path.join(REPO_ROOT, 'examples/voxel', BUNNY), 'utf8'), { source: BUNNY }).disassembly;
        const pathMoves = plan.paths.flat().length;
        const length = plan.steps.length < pathMoves ? plan.steps.length : plan.order.length - 1;
        const unit = plan.steps.length < pathMoves ? 'moves' : 'removals';
        assert.equal(await page.evaluate(() => window.__desiaView.stepsPerSecond), length / 20);
        assert.match(await page.getAttribute('#disassembly-range', 'title'), new RegExp(`^${length} ${unit}, 20 s at 1×$`));
        assert.equal((await partsState(page)).count, 80);
        await page.locator('#disassembly-range').fill('40');
        const removed = unit === 'moves' ? plan.steps.slice(0, 40).filter((step) => step.out && step.parts.length === 1).length : 40;
        assert.equal((await partsState(page)).tray, removed);
        await screenshot(page, `parts-${size}-bunny-tray`);
        await page.locator('#disassembly-range').fill('0');
        assert.deepEqual(pageErrors, []);
      });
    }
  });
}
