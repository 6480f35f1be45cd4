// SPDX-License-Identifier: GPL-3.0-or-later
//
// Frame structures in the playground (issue 9), in headless Chromium: the FRAME CUBE example is
// drawn (its 12 beams and the bare joint cubes, framed in mm) and checked; Design makes its
// 3x3x3 voxel joints in the worker with progress (interlocking, key 1, the CLI's result document
// for the same seed) and step by step (Next until complete, verified); the disassembly plays each beam along its axis; the result downloads as an
// STL equal to the CLI's export and as .fpuz and CSV; the cut-point frame shows the core's
// message; a bad frame file shows the core's error; an OBJ of lines opens as a frame; the
// 300-beam scaffold designs, and the 882-beam one shows progress and is cancelled.
//
//   node --test tests/browser/frames.test.mjs
//
// Needs what playground.test.mjs needs, plus the native CLI (build/native/core/cli/desia; bash
// scripts/build.sh native). Screenshots go to test-artifacts/frames-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { readFile, writeFile } from 'node:fs/promises';
import path from 'node:path';
import {
  ARTIFACTS_DIR, REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, pageState, screenshot,
  waitForReady, waitForSettled,
} from './support.mjs';

const CUBE = 'frame_cube.json';
const CUT_POINT = 'cut_point.json';
const SCAFFOLD = 'scaffold_300.json';
const LARGE_SCAFFOLD = 'scaffold_882.json';
/** The name the page gives the FRAME CUBE's result with seed 1. */
const CUBE_RESULT = 'frame_cube_frame_seed1.json';
const CLI = path.join(REPO_ROOT, 'build/native/core/cli/desia');
const DESIGN_TIMEOUT_MS = 30_000;

async function designState(page) {
  return page.evaluate(() => ({
    outcome: document.body.dataset.design ?? '',
    message: document.querySelector('#design-message').hidden ? '' : document.querySelector('#design-message').textContent,
    updates: Number(document.querySelector('#design-progress-box').dataset.updates ?? 0),
    progressText: document.querySelector('#design-progress-text').textContent,
    kind: document.querySelector('#design-panel').dataset.kind,
  }));
}

/** Clicks Design and waits for its outcome. */
async function design(page, fields = {}) {
  for (const [name, value] of Object.entries(fields)) await page.fill(`#design-form [name="${name}"]`, String(value));
  await page.click('#design-button');
  await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: DESIGN_TIMEOUT_MS });
  return designState(page);
}

async function viewState(page) {
  return page.evaluate(() => ({
    positions: window.__desiaView.partPositions(),
    steps: window.__desiaView.steps,
    label: document.querySelector('#disassembly-step').textContent,
    moves: document.querySelector('#disassembly-moves').textContent,
  }));
}

async function setStep(page, value) {
  await page.evaluate((step) => {
    const range = document.querySelector('#disassembly-range');
    range.value = String(step);
    range.dispatchEvent(new Event('input'));
  }, value);
}

/** Exports the assembly on screen in `format`; resolves with the download. */
async function exportAs(page, format) {
  await page.selectOption('#export-format', format);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-button')]);
  return download;
}

describe('frame structures in the playground (headless Chromium)', { timeout: 180_000 }, () => {
  let browser;
  let server;
  let page;
  const pageErrors = [];

  before(async () => {
    checkPrerequisites();
    for (const file of [CUBE, CUT_POINT, SCAFFOLD]) {
      if (!existsSync(path.join(REPO_ROOT, 'examples/frame', file))) throw new Error(`examples/frame/${file} is missing`);
    }
    if (!existsSync(CLI)) throw new Error(`the native CLI is missing: run bash scripts/build.sh native (${CLI} not found)`);
    browser = await openBrowser({ acceptDownloads: true, viewport: { width: 1400, height: 900 } });
    ({ server, page } = browser);
    page.on('pageerror', (error) => pageErrors.push(error.message));
  });

  after(async () => {
    await browser?.close();
  });

  it('lists the frame examples and draws the FRAME CUBE with its beams and joint cubes', async () => {
    await page.goto(server.url);
    const groups = await page.$$eval('#example-select optgroup', (list) => list.map((group) => ({
      label: group.label, files: [...group.querySelectorAll('option')].map((option) => option.value),
    })));
    const frames = groups.find((group) => group.label === 'Frame structures');
    assert.ok(frames, `no "Frame structures" group: ${JSON.stringify(groups.map((group) => group.label))}`);
    assert.deepEqual(frames.files.slice(0, 7), [CUBE, 'frame_chair.json', 'flower.json', 'scaffold_92.json', SCAFFOLD, LARGE_SCAFFOLD, CUT_POINT]);

    await page.selectOption('#example-select', CUBE);
    const state = await waitForReady(page, CUBE);
    // A frame without joints is an input to design from, said neutrally (issue 28, item 5).
    assert.equal(state.verdictCode, 'input', 'a frame without joints is not interlocking');
    assert.equal(state.verdict, 'Frame: 12 beams, ready to design joints');
    assert.equal(state.parts, '12');
    if (state.webgl === 'on') {
      assert.equal(state.meshes, '13', '12 beams and the bare joint cubes');
      // In mm: the cube is 600 mm with 120 mm joint cubes, 720 mm across.
      const framing = await page.evaluate(() => window.__desiaView.framing());
      assert.ok(framing.distance > 900 && framing.distance < 6000, `camera distance ${framing.distance}`);
      assert.equal(framing.gridCell, 50);
      assert.equal(framing.removalStep, 360);
    }
    // The Design panel designs frame joints: N, ranking, mode hidden, 2 candidates as FrameInterlock.
    assert.equal((await designState(page)).kind, 'frame');
    for (const selector of ['#design-parts', '#design-rank', '#design-mode', '#design-joints', '#design-clearance']) {
      assert.equal(await page.isDisabled(selector), true, `${selector} is disabled for frames`);
      assert.equal(await page.isHidden(selector), true, `${selector} is hidden for frames`);
    }
    assert.equal(await page.isVisible('#design-frame-note'), true);
    assert.equal(await page.isVisible('#design-frame-hint'), true);
    assert.equal(await page.inputValue('#design-candidates'), '2');
    assert.equal(await page.isDisabled('#session-start'), false, 'frames design step by step too');
    // Frame formats: .fpuz and CSV need designed joints: greyed for an input, with the core's reason
    // in the panel (issue 28); .puz is voxel-only.
    assert.equal(await page.locator('#export-format option[value="puz"]').isDisabled(), true);
    assert.equal(await page.locator('#export-format option[value="svg"]').isDisabled(), true);
    await page.waitForFunction(() => document.querySelector('#export-format option[value="fpuz"]').disabled);
    assert.match(await page.textContent('#export-unavailable'), /^\.fpuz is greyed out: this frame has no designed joints yet/);
    // The kinds come from the core's registry (exportFormats): it writes .xmpuzzle for frames too,
    // once designed, so an input greys it with the core's reason; SVG is for plates only.
    await page.waitForFunction(() => document.querySelector('#export-format option[value="xmpuzzle"]').disabled);
    assert.match(await page.textContent('#export-unavailable'), /\.xmpuzzle is greyed out: this frame has no designed joints yet/);
    assert.equal(await page.locator('#export-format option[value="stl"]').isDisabled(), false);
    await screenshot(page, 'frames-cube-1400');
  });

  it('designs the FRAME CUBE step by step: the key leaves upwards, Next until complete gives a verified design', async () => {
    await page.$eval('#session-details', (details) => { details.open = true; });
    assert.equal(await page.isVisible('#session-plate-note'), true);
    await page.click('#session-start');
    await page.waitForFunction(() => document.querySelector('#session-state').dataset.parts === '1');
    assert.match(await page.textContent('#session-state'), /^1 of 12 beams \(the last is the remainder\) · \d+ children/);
    await page.click('#session-preview');
    await page.waitForFunction(() => /^Child 0:/.test(document.querySelector('#design-message').textContent));
    assert.match(await page.textContent('#design-message'),
      /^Child 0: beam \d+ leaves along \+y \(free voxels taken: \d+ at joint \d+, \d+ at joint \d+\)\. Choose it/);
    for (let parts = 2; parts <= 12; parts += 1) {
      await page.click('#session-next');
      await page.waitForFunction((n) => document.querySelector('#session-state').dataset.parts === String(n), parts);
    }
    assert.equal(await page.getAttribute('#session-state', 'data-complete'), 'true');
    assert.match(await page.textContent('#session-state'), /^Complete: 12 of 12 beams, verified\.$/);
    const stepped = await pageState(page);
    assertInterlockingWithKey(stepped, 1);
    assert.equal(stepped.parts, '12');
    await screenshot(page, 'frames-cube-stepped-1400');
    await page.click('#session-close');
    await page.selectOption('#example-select', CUBE);
    await waitForReady(page, CUBE);
  });

  it('designs the FRAME CUBE in the worker: interlocking with key 1, the CLI\'s document, the disassembly along each beam\'s axis', async () => {
    const outcome = await design(page, { seed: 1 });
    assert.equal(outcome.outcome, 'success', `design failed: ${outcome.message}`);
    assert.match(outcome.message, /^designed the joints of 12 beams \(key: beam 1(, input beam \d+)?\) in \d+ nodes$/);
    assert.ok(outcome.updates >= 1, 'the last progress message arrived');
    assert.match(outcome.progressText, /^12 of 12 beams placed · \d+ nodes visited · depth \d+ · \d+\.\d s$/);

    const state = await waitForReady(page, CUBE_RESULT);
    assertInterlockingWithKey(state, 1);
    assert.equal(state.parts, '12');
    assert.equal(state.error, '');
    const paths = await page.$$eval('#paths li', (items) => items.map((item) => item.textContent));
    assert.equal(paths.length, 12);
    assert.match(paths[0], /^beam 1: along [+-][xyz]$/);
    assert.equal(paths[11], 'beam 12: stays (last part)');

    // The same document as the CLI's for the same seed.
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-button')]);
    assert.equal(download.suggestedFilename(), CUBE_RESULT);
    const text = await readFile(await download.path(), 'utf8');
    const file = path.join(ARTIFACTS_DIR, CUBE_RESULT);
    await writeFile(file, text);
    const cliFile = path.join(ARTIFACTS_DIR, 'frame_cube_cli_seed1.json');
    const cli = spawnSync(CLI, ['design', 'frame', '--input', path.join(REPO_ROOT, 'examples/frame', CUBE), '--seed', '1', '--output', cliFile], { encoding: 'utf8' });
    assert.equal(cli.status, 0, cli.stderr);
    assert.equal(JSON.stringify(JSON.parse(text)), JSON.stringify(JSON.parse(await readFile(cliFile, 'utf8'))));
    const check = spawnSync(CLI, ['check', file], { encoding: 'utf8' });
    assert.equal(check.status, 0, `${check.stdout}${check.stderr}`);
    assert.match(check.stdout, /verdict: interlocking/);

    if (state.webgl === 'on') {
      assert.equal(state.meshes, '12', 'one mesh per beam with its joint voxels');
      const removal = JSON.parse(text).removal;
      const assembled = await viewState(page);
      assert.equal(assembled.steps, 11, 'eleven beams leave, the last stays');
      // Halfway through the first removal, the key moves along its axis only, by hundreds of mm.
      await setStep(page, 0.5);
      const moving = await viewState(page);
      const axis = 'xyz'.indexOf(removal[0].direction[1]);
      const sign = removal[0].direction[0] === '+' ? 1 : -1;
      for (let k = 0; k < 3; k += 1) {
        const moved = moving.positions[1][k] - assembled.positions[1][k];
        if (k === axis) assert.ok(sign * moved > 100, `beam 1 moved ${moved} along ${removal[0].direction}`);
        else assert.equal(moved, 0);
      }
      assert.deepEqual(moving.positions[2], assembled.positions[2], 'the others wait');
      assert.equal(moving.label, 'removing part 1 (1 of 11)');
      assert.equal(moving.moves, `along ${removal[0].direction}`);
      await screenshot(page, 'frames-cube-removing-1400');
      // Played to the end: every beam but the last is gone.
      await page.click('#disassembly-play');
      await page.waitForFunction(() => Number(document.querySelector('#viewport').dataset.step) >= 11, null, { timeout: 30_000 });
      const end = await viewState(page);
      assert.equal(end.positions[1], undefined, 'beam 1 is gone');
      assert.ok(end.positions[12], 'beam 12 stays');
      await setStep(page, 0);
    }
    await screenshot(page, 'frames-cube-designed-1400');
  });

  it('downloads the designed cube as the CLI\'s STL, .fpuz and CSV cut list', async () => {
    const file = path.join(ARTIFACTS_DIR, CUBE_RESULT);
    const stl = await exportAs(page, 'stl');
    assert.equal(stl.suggestedFilename(), 'frame_cube_frame_seed1.stl');
    const bytes = await readFile(await stl.path());
    const cliStl = path.join(ARTIFACTS_DIR, 'frame_cube_cli.stl');
    assert.equal(spawnSync(CLI, ['export', file, '--format', 'stl', '--output', cliStl]).status, 0);
    assert.ok(bytes.equals(await readFile(cliStl)), 'the same STL bytes as the CLI');
    assert.equal(bytes.readUInt32LE(80) * 50 + 84, bytes.length);
    assert.match(await page.textContent('#export-message'), /^Saved frame_cube_frame_seed1\.stl \([\d,]+ bytes\)\.$/);

    const fpuz = await exportAs(page, 'fpuz');
    assert.equal(fpuz.suggestedFilename(), 'frame_cube_frame_seed1.fpuz');
    const csv = await exportAs(page, 'csv');
    const table = await readFile(await csv.path(), 'utf8');
    assert.equal(table.trim().split('\n').length, 13, 'a header and one row per beam');

    // The .fpuz opens again as the user's own file: the same verdict.
    await page.setInputFiles('#file-input', { name: 'cube.fpuz', mimeType: 'text/plain', buffer: await readFile(await fpuz.path()) });
    const state = await waitForReady(page, 'cube.fpuz');
    assertInterlockingWithKey(state, 1);
    assert.equal((await designState(page)).kind, 'frame');
  });

  it('flags the cut-point frame\'s beam at once, and shows its message after Design', async () => {
    await page.selectOption('#example-select', CUT_POINT);
    await waitForReady(page, CUT_POINT);
    // Before Design, from the core's check of the input (cutPoints), as for a plate structure.
    assert.equal(await page.isVisible('#cut-points'), true);
    assert.equal(await page.textContent('#cut-points'),
      'Cut point: beam 9 — no joints can make this interlocking; add a part that bypasses it.');
    await screenshot(page, 'frames-cut-point-before-design-1400');
    const outcome = await design(page, { seed: 1 });
    assert.equal(outcome.outcome, 'cut-point');
    assert.match(outcome.message, /^beam 9 is a cut point of the parts-graph/);
    const state = await pageState(page);
    assert.equal(state.status, 'ready', 'a cut point is an answer, not a crash');
    assert.equal(state.source, CUT_POINT);
  });

  it('shows the core\'s error for a bad frame file, and opens an OBJ of lines as a frame', async () => {
    const bad = '{"format": "desia-assembly", "version": 1, "kind": "frame", "joints": [[0,0,0],[100,0,0]], "beams": [[1,1]]}';
    await page.setInputFiles('#file-input', { name: 'bad_frame.json', mimeType: 'application/json', buffer: Buffer.from(bad) });
    const state = await waitForSettled(page, 'bad_frame.json');
    assert.equal(state.status, 'error');
    assert.match(state.error, /^bad_frame\.json: .*beam/);
    // The message is the core's: the same as the CLI's for that file.
    const file = path.join(ARTIFACTS_DIR, 'bad_frame.json');
    await writeFile(file, bad);
    const cli = spawnSync(CLI, ['check', file], { encoding: 'utf8' });
    assert.equal(cli.status, 2);
    assert.ok(cli.stderr.includes(state.error.replace(/^bad_frame\.json/, '')), `${cli.stderr} vs ${state.error}`);

    const obj = ['v 0 0 0', 'v 400 0 0', 'v 400 400 0', 'v 0 400 0', 'v 0 0 400', 'v 400 0 400', 'v 400 400 400', 'v 0 400 400',
      'l 1 2', 'l 2 3', 'l 3 4', 'l 4 1', 'l 5 6', 'l 6 7', 'l 7 8', 'l 8 5', 'l 1 5', 'l 2 6', 'l 3 7', 'l 4 8'].join('\n');
    await page.setInputFiles('#file-input', { name: 'box.obj', mimeType: 'model/obj', buffer: Buffer.from(obj) });
    const opened = await waitForReady(page, 'box.json');
    assert.equal(opened.parts, '12');
    assert.equal((await designState(page)).kind, 'frame');
    const outcome = await design(page, { seed: 1 });
    assert.equal(outcome.outcome, 'success', outcome.message);
    assertInterlockingWithKey(await waitForReady(page, 'box_frame_seed1.json'), 1);
  });

  it('designs the 300-beam scaffold', async () => {
    await page.selectOption('#example-select', SCAFFOLD);
    const state = await waitForReady(page, SCAFFOLD);
    assert.equal(state.parts, '300');
    const outcome = await design(page, { seed: 1 });
    assert.equal(outcome.outcome, 'success', `design failed: ${outcome.message}`);
    assert.match(outcome.message, /^designed the joints of 300 beams \(key: beam 1(, input beam \d+)?\) in \d+ nodes$/);
    const result = await waitForReady(page, 'scaffold_300_frame_seed1.json');
    assertInterlockingWithKey(result, 1);
    assert.equal(result.parts, '300');
  });

  it('shows progress for the 882-beam scaffold and cancels it', async () => {
    await page.selectOption('#example-select', LARGE_SCAFFOLD);
    const state = await waitForReady(page, LARGE_SCAFFOLD);
    assert.equal(state.parts, '882');
    await page.click('#design-button');
    // A timer, not animation frames: software WebGL drawing the live design can hold frames back
    // for seconds, and the design would end before Cancel is reached.
    await page.waitForFunction(() => Number(document.querySelector('#design-progress-box').dataset.updates) >= 2, null, { timeout: 20_000, polling: 50 });
    const running = await designState(page);
    assert.equal(running.outcome, 'running');
    assert.match(running.progressText, /^\d+ of 882 beams placed · \d+ nodes visited/);
    await page.click('#design-cancel');
    await page.waitForFunction(() => document.body.dataset.design === 'cancelled' && document.body.dataset.core === 'ready');
    assert.match((await designState(page)).message, /^Cancelled after \d+\.\d s: the deepest node had \d+ of 882 beams/);
    assert.equal((await pageState(page)).source, LARGE_SCAFFOLD);
  });

  it('switches back to voxels with the voxel designer\'s candidates', async () => {
    await page.selectOption('#example-select', 'Cube_4x4x4_origin.puz');
    await waitForReady(page, 'Cube_4x4x4_origin.puz');
    assert.equal((await designState(page)).kind, 'voxel');
    assert.equal(await page.inputValue('#design-candidates'), '30');
    assert.equal(await page.isHidden('#design-frame-note'), true);
    assert.deepEqual(pageErrors, []);
  });
});
