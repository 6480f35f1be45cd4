// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multi-part disassemblies in the playground (issue 27), in headless Chromium: BurrTools' example
// puzzles (tests/data/burrtools) opened as the user's file. The Pelikan burr (level 98.2.5, 108
// moves, no single-part paths) shows its level beside the verdict, lists its moves, plays move by
// move ("move 1 of 108" -> "move 2 of 108") with the parts moved together marked (in the view, on
// the playback bar and in the list) and moved by exactly the move's offset while the others stand
// still; a six-piece burr whose first move takes three parts out together moves those three clear
// of the others, then the next part out goes to the tray; CubeInCage (a partial plan, parts 1, 2,
// 3 stuck together) plays to where it stops and names the stuck parts; the 9-part cube, whose
// single-part paths are as short as its moves, still plays part by part.
//
//   node --test tests/browser/moves.test.mjs
//
// The reference reports come from the same WebAssembly core in node. Screenshots go to
// test-artifacts/moves-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import { REPO_ROOT, checkPrerequisites, openBrowser, screenshot, waitForReady } from './support.mjs';

const BURRTOOLS = path.join(REPO_ROOT, 'tests/data/burrtools');
const PELIKAN = 'PelikanBurr-p0-s0.puz';
const SIX_PIECE = 'SolidSixPieceBurrs-p0-s0.puz';
const CUBE_IN_CAGE = 'CubeInCage-p0-s0.puz';
const CUBE = 'Cube_4x4x4_K9.puz';

let core = null;
/** The core's report for a BurrTools example, from the WebAssembly module in node. */
async function referenceReport(file, folder = BURRTOOLS) {
  core ??= await loadDesiaModule();
  return core.check(readFileSync(path.join(folder, file), 'utf8'), { source: file });
}

/** Opens a BurrTools example as the user's own file and waits for its report. */
async function openFile(page, file) {
  await page.setInputFiles('#file-input', { name: file, mimeType: 'text/plain', buffer: readFileSync(path.join(BURRTOOLS, file)) });
  return waitForReady(page, file);
}

/** The playback bar, the view's marks and the report's list of moves. */
function movesState(page) {
  return page.evaluate(() => {
    const viewport = document.querySelector('#viewport');
    const level = document.querySelector('#disassembly-level');
    return {
      step: Number(viewport.dataset.step),
      max: Number(document.querySelector('#disassembly-range').max),
      label: document.querySelector('#disassembly-step').textContent,
      moves: document.querySelector('#disassembly-moves').textContent,
      move: viewport.dataset.move,
      moving: viewport.dataset.moving,
      arrow: viewport.dataset.arrow,
      tray: Number(viewport.dataset.tray),
      playing: document.querySelector('#viewer-controls').dataset.playing === 'true',
      viewMoving: window.__desiaView.movingParts,
      level: level.hidden ? '' : level.textContent,
      levelData: level.dataset.level,
      partial: level.dataset.partial,
      listed: Number(document.querySelector('#moves').dataset.count),
      shownItems: [...document.querySelectorAll('#moves li')].filter((item) => !item.hidden).map((item) => item.textContent),
      current: document.querySelector('#moves li[aria-current="step"]')?.textContent ?? '',
      currentParts: document.querySelector('#moves li[aria-current="step"]')?.dataset.parts ?? '',
      currentPath: document.querySelector('#paths li[aria-current="step"]')?.textContent ?? '',
      order: document.querySelector('#order').textContent,
    };
  });
}

const positions = (page) => page.evaluate(() => window.__desiaView.partPositions());

/** Next ›, then wait until the animation has stopped on the next whole step. */
async function next(page) {
  const before = (await movesState(page)).step;
  await page.click('#disassembly-next');
  await page.waitForFunction((from) => {
    const step = Number(document.querySelector('#viewport').dataset.step);
    return document.querySelector('#viewer-controls').dataset.playing === 'false' && step >= from + 1 - 1e-6;
  }, before, { timeout: 10_000 });
  return movesState(page);
}

const close = (a, b) => a.every((value, axis) => Math.abs(value - b[axis]) < 1e-6);
const offset = (from, to) => to.map((value, axis) => value - from[axis]);

describe('multi-part disassemblies in the playground', { timeout: 180_000 }, () => {
  let browser;
  let server;
  let page;
  const pageErrors = [];

  before(async () => {
    checkPrerequisites([CUBE]);
    browser = await openBrowser({ viewport: { width: 1400, height: 900 } });
    ({ server, page } = browser);
    page.on('pageerror', (error) => pageErrors.push(error.message));
    await page.goto(`${server.url}?example=${CUBE}`);
    await waitForReady(page, CUBE);
  });

  after(async () => {
    await browser?.close();
  });

  it('shows the Pelikan burr\'s level and moves, and plays it move by move with the moving parts marked', async (t) => {
    const report = await referenceReport(PELIKAN);
    const plan = report.disassembly;
    assert.equal(plan.paths, null, 'the Pelikan burr needs parts moved together');
    assert.equal(plan.level[0], 98);
    const state = await openFile(page, PELIKAN);
    assert.equal(state.verdictCode, report.verdict);

    let moves = await movesState(page);
    assert.equal(moves.level, `level ${plan.level.join('.')}, ${plan.moves} moves`);
    assert.match(moves.level, /^level 98\.2\.5, 108 moves$/);
    assert.equal(moves.levelData, '98.2.5');
    assert.equal(moves.listed, 108);
    // The long list is shortened as the removal order is: the first 8, "… 98 more", the last 2.
    assert.equal(moves.shownItems.length, 11, moves.shownItems.join(' | '));
    assert.equal(moves.shownItems[0], `move 1: ${plan.steps[0].parts.length === 1 ? 'part' : 'parts'} ${plan.steps[0].parts.join(', ')}  ${axisText(plan.steps[0])}`);
    assert.match(moves.shownItems[8], /98 more moves/);
    assert.match(moves.shownItems[10], /^move 108: parts? [\d, ]+ {2}[+-][xyz] (out|\d+)$/);
    await screenshot(page, 'moves-pelikan-report');

    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium: nothing is animated');
    assert.equal(moves.max, 108, 'the slider runs over the 108 moves');
    assert.equal(moves.label, 'assembled');
    assert.equal(moves.moving, '');
    const assembled = await positions(page);
    assert.equal(Object.keys(assembled).length, report.parts);

    for (let index = 0; index < 3; index += 1) {
      const before = await positions(page);
      moves = await next(page);
      const step = plan.steps[index];
      const parts = step.parts.join(' ');
      assert.equal(moves.label, `move ${index + 1} of 108`);
      assert.equal(moves.move, String(index + 1));
      assert.equal(moves.moving, parts, 'the view marks the parts moved together');
      assert.deepEqual(moves.viewMoving, step.parts);
      assert.equal(moves.arrow, parts, 'the arrow is drawn from the parts moved together');
      assert.equal(moves.moves, `${step.parts.length === 1 ? 'part' : 'parts'} ${step.parts.join(', ')}  ${axisText(step)}`);
      assert.equal(moves.current, `move ${index + 1}: ${moves.moves}`, 'the list marks the move played');
      assert.equal(moves.currentParts, parts);
      assert.equal(moves.currentPath, '', 'no removal path is marked');
      // The parts of the move went by exactly its offset; every other part stood still.
      const after = await positions(page);
      for (const partId of Object.keys(assembled)) {
        const expected = step.parts.includes(Number(partId)) ? step.move : [0, 0, 0];
        assert.ok(close(offset(before[partId], after[partId]), expected),
          `move ${index + 1}: part ${partId} moved ${offset(before[partId], after[partId])}, expected ${expected}`);
      }
      if (index === 0) await screenshot(page, 'moves-pelikan-move-1');
    }
    assert.ok(plan.steps.slice(0, 3).some((step) => step.parts.length > 1), 'the first moves include parts moved together');

    // Back one move: the parts of move 2 marked again, the third move undone.
    await page.click('#disassembly-prev');
    await page.waitForFunction(() => document.querySelector('#viewer-controls').dataset.playing === 'false'
      && Number(document.querySelector('#viewport').dataset.step) === 2);
    moves = await movesState(page);
    assert.equal(moves.label, 'move 2 of 108');
    assert.equal(moves.moving, plan.steps[1].parts.join(' '));

    // The slider to the end: every part is out, the last move marked, and it is in the list
    // although the list is short.
    await page.locator('#disassembly-range').fill('108');
    moves = await movesState(page);
    assert.equal(moves.label, 'move 108 of 108');
    assert.equal(moves.moving, plan.steps[107].parts.join(' '));
    assert.ok(moves.shownItems.some((item) => item.startsWith('move 108: ')));
    await page.locator('#disassembly-range').fill('50.5');
    moves = await movesState(page);
    assert.equal(moves.label, 'move 51 of 108');
    assert.ok(moves.shownItems.includes(moves.current), 'the move played is shown in the shortened list');
    assert.equal(moves.current, `move 51: ${moves.moves}`);
    await page.locator('#disassembly-range').fill('0');
    assert.deepEqual(pageErrors, []);
  });

  it('moves a six-piece burr\'s three parts out together, clear of the others', async (t) => {
    const report = await referenceReport(SIX_PIECE);
    const plan = report.disassembly;
    const [first, second] = plan.steps;
    assert.ok(first.out && first.parts.length >= 2, `the first move takes several parts out: ${JSON.stringify(first)}`);
    const state = await openFile(page, SIX_PIECE);
    let moves = await movesState(page);
    assert.equal(moves.level, `level ${plan.level.join('.')}, ${plan.moves} move${plan.moves === 1 ? '' : 's'}`);
    assert.equal(moves.shownItems[0], `move 1: parts ${first.parts.join(', ')}  ${axisText(first)}`);
    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');

    const assembled = await positions(page);
    moves = await next(page);
    assert.equal(moves.label, `move 1 of ${plan.steps.length}`);
    assert.equal(moves.moving, first.parts.join(' '));
    const out = await positions(page);
    const axis = first.move.findIndex((value) => value !== 0);
    const shifts = first.parts.map((partId) => offset(assembled[partId], out[partId]));
    // The group moved together, along the move's axis only, and stays in the view.
    for (const shift of shifts) assert.ok(close(shift, shifts[0]), `the group moved as one: ${JSON.stringify(shifts)}`);
    assert.ok(shifts[0][axis] * first.move[axis] > 0, `moved along ${axisText(first)}: ${shifts[0]}`);
    assert.ok(shifts[0].every((value, other) => other === axis || value === 0));
    // Clear of the rest: the group's bounds and the others' no longer overlap along the axis.
    const bounds = await page.evaluate((ids) => Object.fromEntries(ids.map((id) => [id, window.__desiaView.partBounds(id)])), report.partIds);
    const rest = report.partIds.filter((partId) => !first.parts.includes(partId));
    const sign = Math.sign(first.move[axis]);
    const groupNear = Math.min(...first.parts.map((id) => sign * (sign > 0 ? bounds[id].min[axis] : bounds[id].max[axis])));
    const restFar = Math.max(...rest.map((id) => sign * (sign > 0 ? bounds[id].max[axis] : bounds[id].min[axis])));
    assert.ok(groupNear >= restFar - 1e-6, `the group clears the others: ${groupNear} vs ${restFar}`);
    for (const partId of rest) assert.ok(close(assembled[partId], out[partId]), `part ${partId} stood still`);
    assert.equal(moves.tray, 0, 'a group that goes out is not in the tray');
    await screenshot(page, 'moves-six-piece-1');

    // The next one goes out alone: it lands in the tray, as removed parts do.
    moves = await next(page);
    assert.equal(second.parts.length, 1);
    assert.equal(moves.moving, String(second.parts[0]));
    assert.equal(moves.tray, 1);
    const tray = await page.evaluate(() => window.__desiaView.trayPositions());
    assert.deepEqual(Object.keys(tray), [String(second.parts[0])]);
    assert.deepEqual(pageErrors, []);
  });

  it('plays a partial plan up to where it stops and names the stuck parts', async (t) => {
    const report = await referenceReport(CUBE_IN_CAGE);
    const failure = report.disassemblyFailure;
    assert.equal(report.disassembly, null);
    assert.ok(failure.steps.length > 0 && failure.unseparated.length > 0);
    const state = await openFile(page, CUBE_IN_CAGE);
    let moves = await movesState(page);
    const stuck = failure.unseparated.map((group) => `parts ${group.join(', ')}`).join(' and ');
    assert.equal(moves.partial, 'true');
    assert.equal(moves.level, `Partial plan: level ${failure.level.join('.')}, ${failure.steps.length} moves, then ${stuck} are stuck together`);
    assert.match(moves.order, new RegExp(`${stuck} are stuck together$`));
    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
    const count = failure.steps.length;
    assert.equal(moves.max, count);
    await page.locator('#disassembly-range').fill(String(count));
    moves = await movesState(page);
    assert.equal(moves.label, `move ${count} of ${count}`);
    assert.match(moves.moves, new RegExp(`; then ${stuck} are stuck together$`));
    await screenshot(page, 'moves-cube-in-cage-end');
    assert.deepEqual(pageErrors, []);
  });

  it('still plays the paper\'s puzzles part by part', async (t) => {
    await page.selectOption('#example-select', CUBE);
    const state = await waitForReady(page, CUBE);
    const report = await referenceReport(CUBE, path.join(REPO_ROOT, 'examples/voxel'));
    const plan = report.disassembly;
    assert.ok(plan.paths !== null && plan.steps.length >= plan.paths.flat().length, 'the paths are as short as the moves');
    const moves = await movesState(page);
    assert.equal(moves.level, `level ${plan.level.join('.')}, ${plan.moves} moves`);
    assert.equal(moves.shownItems.length, plan.steps.length);
    assert.equal(moves.shownItems[0], `move 1: part ${plan.steps[0].parts[0]}  ${axisText(plan.steps[0])}`);
    if (state.webgl !== 'on') return t.skip('no WebGL in this Chromium');
    assert.equal(moves.max, 8, 'eight removals, as before');
    const after = await next(page);
    assert.match(after.label, /^removing part \d+ \(2 of 8\)$/);
    assert.equal(after.moving, '');
    assert.equal(after.current, '', 'no move is marked');
    assert.match(after.currentPath, /^part \d+: /);
    assert.deepEqual(pageErrors, []);
  });
});

/** '+x 1', '-z 6', '+y out', as the CLI writes a step's move. */
function axisText(step) {
  const axis = step.move.findIndex((value) => value !== 0);
  const value = step.move[axis];
  return `${value > 0 ? '+' : '-'}${'xyz'[axis]} ${step.out ? 'out' : Math.abs(value)}`;
}
