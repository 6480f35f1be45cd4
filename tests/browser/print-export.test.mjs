// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Export panel's print-ready formats in headless Chromium (issue 11): the voxel size and
// clearance fields appear for "STL per part, ZIP" and "STL build plate" only; the downloads are
// named <name>.zip and <name>-plate.stl and hold exactly the core's bytes for the values typed
// (one STL per part in the ZIP); a clearance of half a voxel shows the core's message.
//
//   node --test tests/browser/print-export.test.mjs
//
// Screenshot: test-artifacts/print-export.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import { REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, screenshot, waitForReady } from './support.mjs';

const CUBE_PUZZLE = 'Cube_4x4x4_K9.puz';

/** Clicks Export with the format and fields given and returns { name, bytes } of the download. */
async function exportAs(page, format, fields = {}) {
  await page.selectOption('#export-format', format);
  for (const [selector, value] of Object.entries(fields)) await page.fill(selector, value);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-button')]);
  const bytes = new Uint8Array(await readFile(await download.path()));
  await page.waitForFunction(() => document.querySelector('#export-panel').dataset.state === 'done');
  return { name: download.suggestedFilename(), bytes };
}

/** The file names in a ZIP's central directory. */
function zipNames(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const end = bytes.length - 22;
  assert.equal(view.getUint32(end, true), 0x06054b50);
  const names = [];
  let at = view.getUint32(end + 16, true);
  for (let k = 0; k < view.getUint16(end + 10, true); k += 1) {
    const length = view.getUint16(at + 28, true);
    names.push(new TextDecoder().decode(bytes.subarray(at + 46, at + 46 + length)));
    at += 46 + length;
  }
  return names;
}

describe('print-ready exports in the playground', { timeout: 120_000 }, () => {
  let browser;
  let page;
  let core;
  let puzzle;
  const pageErrors = [];

  before(async () => {
    checkPrerequisites([CUBE_PUZZLE]);
    browser = await openBrowser({ acceptDownloads: true });
    page = browser.page;
    page.on('pageerror', (error) => pageErrors.push(error.message));
    core = await loadDesiaModule();
    puzzle = await readFile(path.join(REPO_ROOT, 'examples/voxel', CUBE_PUZZLE), 'utf8');
    await page.goto(`${browser.server.url}?example=${CUBE_PUZZLE}`);
    assertInterlockingWithKey(await waitForReady(page, CUBE_PUZZLE), 1);
  });

  after(async () => {
    await browser?.close();
  });

  it('shows the voxel size and clearance fields for the print-ready formats only', async () => {
    const shown = async () => page.evaluate(() => [...document.querySelectorAll('.export-print')].map((label) => !label.hidden));
    await page.selectOption('#export-format', 'stl');
    assert.deepEqual(await shown(), [false, false]);
    await page.selectOption('#export-format', 'stl-zip');
    assert.deepEqual(await shown(), [true, true]);
    assert.deepEqual([await page.inputValue('#export-voxel-size'), await page.inputValue('#export-clearance')], ['10', '0.2']);
    await page.locator('#export-panel').scrollIntoViewIfNeeded();
    await screenshot(page, 'print-export');
  });

  it('saves <name>.zip with one STL per part, the core\'s bytes for the values typed', async () => {
    const { name, bytes } = await exportAs(page, 'stl-zip', { '#export-voxel-size': '12', '#export-clearance': '0.25' });
    assert.equal(name, 'Cube_4x4x4_K9.zip');
    assert.deepEqual(bytes, core.exportAssembly(puzzle, { format: 'stl-zip', voxelSize: 12, clearance: 0.25, source: CUBE_PUZZLE }));
    assert.deepEqual(zipNames(bytes), Array.from({ length: 9 }, (_, k) => `part-0${k + 1}.stl`));
  });

  it('saves <name>-plate.stl with every part on the build plate', async () => {
    const { name, bytes } = await exportAs(page, 'build-plate-stl', { '#export-voxel-size': '10', '#export-clearance': '0.2' });
    assert.equal(name, 'Cube_4x4x4_K9-plate.stl');
    assert.deepEqual(bytes, core.exportAssembly(puzzle, { format: 'build-plate-stl', voxelSize: 10, clearance: 0.2, source: CUBE_PUZZLE }));
    assert.match(new TextDecoder().decode(bytes.subarray(0, 80)), /^desia build plate, all 9 parts, voxel size 10, clearance 0\.2, spacing 10/);
  });

  it('shows the core\'s message for a clearance of half a voxel', async () => {
    await page.selectOption('#export-format', 'stl-zip');
    await page.fill('#export-voxel-size', '10');
    await page.fill('#export-clearance', '5');
    await page.click('#export-button');
    await page.waitForFunction(() => document.querySelector('#export-panel').dataset.state === 'error');
    assert.equal(await page.textContent('#export-message'),
      `${CUBE_PUZZLE}: the clearance must be at least 0 and less than half the voxel size (5), got 5`);
    assert.deepEqual(pageErrors, []);
  });
});
