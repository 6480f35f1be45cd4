// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's views in headless Chromium: the disassembly animation plays the core's removal
// order to the end and pauses, dragging the slider takes over, the exploded view moves the parts
// apart and back, and the blocking-graph panel draws exactly the graphs of the core's report
// (nodes, edges, components, key), for a 9-part cube, for the 80-part bunny (by components), and
// anew after each step of a design session.
//
//   node --test tests/browser/views.test.mjs
//
// Needs the same as playground.test.mjs; the reference report comes from the native CLI
// (build/native/core/cli/desia) when it is built, else from the WebAssembly module in node.
// Screenshots go to test-artifacts/views-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import {
  REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, screenshot, waitForReady,
} from './support.mjs';

const CUBE = 'Cube_4x4x4_K9.puz';
const BUNNY = 'bunny_15x14x11_K80.puz';
const CUBE_SHAPE = 'Cube_4x4x4_origin.puz';
const NATIVE_CLI = path.join(REPO_ROOT, 'build/native/core/cli/desia');

/** The core's report for an example: `desia check --json` natively, else the same core in node. */
async function referenceReport(file) {
  const examplePath = path.join(REPO_ROOT, 'examples/voxel', file);
  if (existsSync(NATIVE_CLI)) {
    return JSON.parse(execFileSync(NATIVE_CLI, ['check', examplePath, '--json'], { encoding: 'utf8' }));
  }
  const core = await loadDesiaModule();
  return core.check(readFileSync(examplePath, 'utf8'), { source: file });
}

/** The animation's observable state. */
function playbackState(page) {
  return page.evaluate(() => ({
    step: Number(document.querySelector('#viewport').dataset.step),
    max: Number(document.querySelector('#disassembly-range').max),
    slider: Number(document.querySelector('#disassembly-range').value),
    label: document.querySelector('#disassembly-step').textContent,
    moves: document.querySelector('#disassembly-moves').textContent,
    playing: document.querySelector('#viewer-controls').dataset.playing === 'true',
    button: document.querySelector('#disassembly-play').textContent,
    visibleParts: Object.keys(window.__desiaView.partPositions()).length,
    currentPath: document.querySelector('#paths li[aria-current="step"]')?.textContent ?? '',
  }));
}

/** What the DBG panel drew, figure by figure. */
function drawnGraphs(page) {
  return page.evaluate(() => ({
    key: document.querySelector('#dbg-panel').dataset.key,
    notes: [...document.querySelectorAll('#dbg-panel .dbg-note')].map((note) => note.textContent),
    figures: [...document.querySelectorAll('#dbg-panel figure.dbg-graph')].map((figure) => ({
      direction: figure.dataset.direction,
      drawn: figure.dataset.drawn,
      nodes: Number(figure.dataset.nodes),
      edges: Number(figure.dataset.edges),
      components: Number(figure.dataset.components),
      nodeParts: [...figure.querySelectorAll('circle.dbg-node')].map((node) => Number(node.dataset.part)),
      keyNodes: [...figure.querySelectorAll('circle.dbg-node[data-key="true"]')].map((node) => Number(node.dataset.part)),
      edgePairs: [...figure.querySelectorAll('path.dbg-edge')].map((edge) => [Number(edge.dataset.from), Number(edge.dataset.to)]),
      componentBands: figure.querySelectorAll('.dbg-component').length,
      caption: figure.querySelector('figcaption').textContent,
      svgs: figure.querySelectorAll('svg').length,
    })),
  }));
}

const sortPairs = (pairs) => pairs.map((pair) => pair.join('>')).sort();

describe('playground views in headless Chromium', { timeout: 120_000 }, () => {
  let browser;
  let server;
  let page;
  const pageErrors = [];

  before(async () => {
    checkPrerequisites([CUBE, BUNNY, CUBE_SHAPE]);
    browser = await openBrowser();
    ({ server, page } = browser);
    page.on('pageerror', (error) => pageErrors.push(error.message));
  });

  after(async () => {
    await browser?.close();
  });

  it('plays the disassembly to the end, pauses, and gives way to the slider', async (t) => {
    await page.goto(`${server.url}?example=${CUBE}`);
    const state = await waitForReady(page, CUBE);
    assertInterlockingWithKey(state, 1);
    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium: nothing is animated');
    const report = await referenceReport(CUBE);
    const steps = report.disassembly.order.length - 1;

    let playback = await playbackState(page);
    assert.equal(playback.max, steps);
    assert.equal(playback.step, 0);
    assert.equal(playback.label, 'assembled');
    assert.equal(playback.visibleParts, 9);

    // Four steps a second: the 8 removals take about 2 s.
    await page.selectOption('#disassembly-speed', '4');
    await page.click('#disassembly-play');
    playback = await playbackState(page);
    assert.equal(playback.playing, true);
    assert.equal(playback.button, 'Pause');
    await page.waitForFunction(() => Number(document.querySelector('#viewport').dataset.step) >= 1.2);
    playback = await playbackState(page);
    assert.equal(playback.slider, playback.step, 'the slider follows the animation');
    assert.match(playback.label, /^removing part \d+ \(\d of 8\)$/);
    await screenshot(page, 'views-playing');

    await page.waitForFunction(() => document.querySelector('#viewer-controls').dataset.playing === 'false', null, { timeout: 10_000 });
    playback = await playbackState(page);
    assert.equal(playback.step, steps, 'it stops at the end');
    const last = report.disassembly.order[steps];
    assert.equal(playback.label, `part ${last} left`);
    assert.equal(playback.visibleParts, 1, 'every part but the last is removed');
    assert.equal(playback.button, 'Play');

    // Play again starts from assembled; Pause freezes the step. At half speed the 8 removals
    // take 16 s, so the pause click cannot land after the end (and restart it) on a slow machine.
    await page.selectOption('#disassembly-speed', '0.5');
    await page.click('#disassembly-play');
    await page.waitForFunction(() => {
      const step = Number(document.querySelector('#viewport').dataset.step);
      return step > 0.1 && step < 6;
    });
    await page.click('#disassembly-play');
    const paused = await playbackState(page);
    assert.equal(paused.playing, false);
    assert.equal(paused.button, 'Play');
    await page.waitForTimeout(500);
    assert.equal((await playbackState(page)).step, paused.step, 'paused: the step stays');

    // The slider while playing: the animation stops and the slider's step is shown, with the
    // moving part's path from the report and its entry in the removal list.
    await page.click('#disassembly-play');
    await page.locator('#disassembly-range').fill('2.5');
    playback = await playbackState(page);
    assert.equal(playback.playing, false, 'dragging the slider pauses');
    assert.equal(playback.step, 2.5);
    const moving = report.disassembly.order[2];
    assert.equal(playback.label, `removing part ${moving} (3 of 8)`);
    const movesText = report.disassembly.paths[2].map((move) => `${move.dir}×${move.steps}`).join(', then ');
    assert.equal(playback.moves, movesText);
    assert.match(playback.currentPath, new RegExp(`^part ${moving}: `));
    assert.equal(playback.visibleParts, 9 - 2, 'two parts are out, the third is on its way');
    await screenshot(page, 'views-step-2.5');
    t.diagnostic(`step 2.5: ${playback.label}: ${playback.moves}`);
  });

  it('explodes the parts away from the centre and back', async (t) => {
    const state = await waitForReady(page, CUBE);
    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
    await page.locator('#disassembly-range').fill('0');
    const positions = () => page.evaluate(() => window.__desiaView.partPositions());
    const assembled = await positions();
    assert.equal(Object.keys(assembled).length, 9);

    await page.locator('#exploded-range').fill('1');
    const exploded = await positions();
    assert.equal(await page.getAttribute('#viewport', 'data-exploded'), '1.00');
    await screenshot(page, 'views-exploded');
    // Spread = mean distance of the parts' positions from their mean: exploding grows it.
    const spread = (byPart) => {
      const points = Object.values(byPart);
      const mean = [0, 1, 2].map((axis) => points.reduce((sum, point) => sum + point[axis], 0) / points.length);
      return points.reduce((sum, point) => sum + Math.hypot(...point.map((value, axis) => value - mean[axis])), 0) / points.length;
    };
    const moved = Object.keys(assembled).filter((part) => Math.hypot(...assembled[part].map((value, axis) => value - exploded[part][axis])) > 0.5);
    assert.ok(moved.length >= 8, `parts moved: ${moved.join(', ')}`);
    assert.ok(spread(exploded) > spread(assembled) + 1.5, `spread ${spread(assembled)} -> ${spread(exploded)}`);

    // Composes with the disassembly: half-way through the first removal, the key is off its exploded place.
    await page.locator('#disassembly-range').fill('0.5');
    const both = await positions();
    assert.notDeepEqual(both['1'], exploded['1'], 'the key moves along its path from its exploded place');
    assert.deepEqual(both['2'], exploded['2'], 'the other parts stay exploded');

    await page.locator('#disassembly-range').fill('0');
    await page.locator('#exploded-range').fill('0');
    assert.deepEqual(await positions(), assembled, 'explode 0 puts every part back');
  });

  it("draws one blocking graph per base direction, exactly the core's", async () => {
    await waitForReady(page, CUBE);
    const report = await referenceReport(CUBE);
    const drawn = await drawnGraphs(page);
    await page.locator('#dbg-panel').screenshot({ path: path.join(REPO_ROOT, 'test-artifacts/views-dbg-cube.png') });
    assert.equal(drawn.key, '1');
    assert.equal(drawn.figures.length, report.graphs.length);
    assert.equal(drawn.figures.length, report.baseDirections.length);
    report.graphs.forEach((graph, index) => {
      const figure = drawn.figures[index];
      assert.equal(figure.direction, graph.direction);
      assert.equal(figure.drawn, 'parts');
      assert.equal(figure.svgs, 1);
      assert.equal(figure.nodes, 9);
      assert.deepEqual([...figure.nodeParts].sort((a, b) => a - b), report.partIds, `${graph.direction}: one node per part`);
      assert.deepEqual(figure.keyNodes, [1], `${graph.direction}: the key is marked`);
      assert.equal(figure.edges, graph.edges.length);
      assert.deepEqual(sortPairs(figure.edgePairs), sortPairs(graph.edges), `${graph.direction}: the core's edges`);
      assert.equal(figure.components, graph.components.length);
      const bands = graph.components.filter((component) => component.length > 1).length;
      assert.equal(figure.componentBands, bands, `${graph.direction}: one band per component of 2+ parts`);
      assert.match(figure.caption, new RegExp(`^G\\(\\${graph.direction}\\) · ${graph.edges.length} edges · ${graph.components.length} SCCs?`));
    });
    // This cube's key moves along -z: G(+z) has the key as a component of its own.
    const plusZ = drawn.figures.find((figure) => figure.direction === '+z');
    assert.equal(plusZ.components, 2);
    assert.match(plusZ.caption, /2 SCCs: \{1\} \+ \{8 parts\}/);
  });

  it('draws the 80-part bunny part by part, on a canvas to zoom (issue 11)', async () => {
    await page.selectOption('#example-select', BUNNY);
    await waitForReady(page, BUNNY);
    const report = await referenceReport(BUNNY);
    const drawn = await drawnGraphs(page);
    await page.locator('#dbg-panel').screenshot({ path: path.join(REPO_ROOT, 'test-artifacts/views-dbg-bunny.png') });
    assert.ok(drawn.notes.some((note) => /^80 parts: zoom with the wheel or \+ \/ −, drag to pan/.test(note)), 'a note explains the drawing');
    assert.equal(drawn.figures.length, report.graphs.length);
    report.graphs.forEach((graph, index) => {
      const figure = drawn.figures[index];
      assert.equal(figure.drawn, 'parts');
      assert.equal(figure.nodes, 80);
      assert.equal(figure.nodeParts.length, 80);
      assert.equal(figure.edges, graph.edges.length);
      assert.equal(figure.components, graph.components.length);
    });
    // The key's direction (+y): the key is a component by itself, the other 79 parts are one.
    const plusY = drawn.figures.find((figure) => figure.direction === '+y');
    assert.equal(plusY.components, 2);
    assert.deepEqual(plusY.keyNodes, [1]);
    assert.match(plusY.caption, /\{1\} \+ \{79 parts\}/);
  });

  it('redraws the graphs after every step of a design session', async () => {
    await page.goto(`${server.url}?example=${CUBE_SHAPE}&parts=7&seed=1`);
    await waitForReady(page, CUBE_SHAPE);
    const signature = async () => {
      const drawn = await drawnGraphs(page);
      return {
        parts: await page.textContent('#parts-count'),
        nodes: drawn.figures.map((figure) => figure.nodes),
        edges: drawn.figures.map((figure) => sortPairs(figure.edgePairs).join(' ')),
      };
    };
    const shape = await signature();
    assert.deepEqual(shape.nodes, [1, 1, 1], 'a one-part shape: one node per graph');

    await page.click('#session-details summary');
    const step = async (selector) => {
      await page.click(selector);
      await page.waitForFunction(() => document.body.dataset.design !== 'running' && document.body.dataset.status === 'ready');
      return signature();
    };
    const first = await step('#session-start');
    const second = await step('#session-next');
    const third = await step('#session-next');
    await screenshot(page, 'views-session-graphs');
    for (const snapshot of [first, second, third]) {
      const parts = Number(snapshot.parts);
      assert.deepEqual(snapshot.nodes, [parts, parts, parts], 'the drawing has the parts of the assembly shown');
    }
    assert.ok(Number(second.parts) > Number(first.parts) && Number(third.parts) > Number(second.parts), 'each step adds a part');
    assert.notDeepEqual(second.edges, first.edges, 'the graphs change with the step');
    assert.notDeepEqual(third.edges, second.edges, 'the graphs change with the step');
    const back = await step('#session-back');
    assert.deepEqual(back, second, 'back shows the previous graphs again');
  });

  it('throws no page errors', () => {
    assert.deepEqual(pageErrors, []);
  });
});
