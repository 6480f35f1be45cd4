// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh assemblies in the playground and the drop-in viewer (issue 29), in headless Chromium at
// 1400x900 and 390x844: the nine parts of a voxel puzzle dropped as nine binary STL files, picked
// as one OBJ of nine objects, and a 3MF written by lib3mf: the parts drawn in their colours, the
// verdict and key of the package's own check of the same files, the blocking graphs, the
// disassembly played to the end and the exploded view; a bad mesh shows the core's message naming
// the file and line; the viewer draws a mesh assembly from `meshes` and from a 3MF `src`. A mesh
// assembly is checked, not designed: the Design panel says so and keeps its input, Export says why
// it offers nothing.
//
//   node --test tests/browser/meshes.test.mjs
//
// Screenshots go to test-artifacts/meshes-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import { REPO_ROOT, checkPrerequisites, openBrowser, screenshot, waitForReady, waitForSettled } from './support.mjs';

const NINE = 'Cube_4x4x4_K9.puz';
const WAGON = path.join(REPO_ROOT, 'tests/data/meshes/WagonWithWheels.3mf');

checkPrerequisites([NINE]);
const core = await loadDesiaModule();
const puzzle = readFileSync(path.join(REPO_ROOT, 'examples/voxel', NINE), 'utf8');
const partStls = Array.from({ length: 9 }, (unused, k) => ({
  name: `part${k + 1}.stl`,
  bytes: Buffer.from(core.exportAssembly(puzzle, { format: 'stl', part: k + 1 })),
}));
const puzzleObj = Buffer.from(core.exportAssembly(puzzle, { format: 'obj' }));

/**
 * A tube (hole of radius 5) and a round pin through it, both of 24 sides, as one OBJ: the pin's
 * sides lie on the hole's, a curved contact region of 24 facets.
 */
function pinInHoleObj(sides = 24) {
  const lines = [];
  const ring = (radius, z) => {
    for (let k = 0; k < sides; k += 1) {
      const angle = (2 * Math.PI * k) / sides;
      lines.push(`v ${radius * Math.cos(angle)} ${radius * Math.sin(angle)} ${z}`);
    }
  };
  const at = (ringIndex, k) => ringIndex * sides + (k % sides) + 1;
  lines.push('o tube');
  ring(10, 0); ring(10, 10); ring(5, 0); ring(5, 10);
  for (let k = 0; k < sides; k += 1) {
    lines.push(`f ${at(0, k)} ${at(0, k + 1)} ${at(1, k + 1)} ${at(1, k)}`, `f ${at(2, k)} ${at(3, k)} ${at(3, k + 1)} ${at(2, k + 1)}`,
      `f ${at(3, k)} ${at(1, k)} ${at(1, k + 1)} ${at(3, k + 1)}`, `f ${at(2, k)} ${at(2, k + 1)} ${at(0, k + 1)} ${at(0, k)}`);
  }
  lines.push('o pin');
  ring(5, -5); ring(5, 15);
  for (let k = 0; k < sides; k += 1) lines.push(`f ${at(4, k)} ${at(4, k + 1)} ${at(5, k + 1)} ${at(5, k)}`);
  for (let k = 1; k + 1 < sides; k += 1) lines.push(`f ${at(5, 0)} ${at(5, k)} ${at(5, k + 1)}`, `f ${at(4, 0)} ${at(4, k + 1)} ${at(4, k)}`);
  return Buffer.from(`${lines.join('\n')}\n`);
}

/** Drops files on the page as a user would (one drop event carrying them all). */
async function dropFiles(page, files) {
  const dataTransfer = await page.evaluateHandle((list) => {
    const transfer = new DataTransfer();
    for (const { name, content } of list) transfer.items.add(new File([new Uint8Array(content)], name));
    return transfer;
  }, files.map(({ name, bytes }) => ({ name, content: [...bytes] })));
  await page.dispatchEvent('body', 'dragenter', { dataTransfer });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

async function playToTheEnd(page) {
  await page.selectOption('#disassembly-speed', '4');
  await page.click('#disassembly-play');
  await page.waitForFunction(() => document.querySelector('#viewer-controls').dataset.playing === 'false', null, { timeout: 20_000 });
  return page.evaluate(() => ({
    step: Number(document.querySelector('#viewport').dataset.step),
    max: Number(document.querySelector('#disassembly-range').max),
    label: document.querySelector('#disassembly-label')?.textContent ?? '',
  }));
}

for (const [width, height] of [[1400, 900], [390, 844]]) {
  describe(`mesh assemblies at ${width}x${height}`, () => {
    let browser;
    let page;
    const errors = [];
    const shot = (name) => screenshot(page, `meshes-${width}-${name}`);

    before(async () => {
      browser = await openBrowser({ viewport: { width, height } });
      page = browser.page;
      page.on('pageerror', (error) => errors.push(error.message));
      await page.goto(browser.server.url);
      await waitForReady(page, 'Cube_4x4x4_origin.puz');
    });

    after(async () => {
      await browser?.close();
    });

    it('nine STL files dropped at once: one assembly, the package\'s verdict, graphs, played and exploded', async () => {
      const expected = core.check({ files: partStls });
      await dropFiles(page, partStls);
      const state = await waitForReady(page, 'part1.stl + 8 more');
      await shot('dropped');
      assert.equal(state.verdictCode, expected.verdict);
      assert.equal(state.key, String(expected.key));
      assert.equal(state.meshes, '9', 'parts drawn');
      assert.equal(await page.evaluate(() => document.body.dataset.meshAssembly), 'part1.stl + 8 more');
      const graphs = await page.evaluate(() => document.querySelectorAll('#dbg-panel figure.dbg-graph').length);
      assert.ok(graphs >= 1, 'the blocking graphs are drawn');
      const played = await playToTheEnd(page);
      assert.equal(played.step, played.max, `played to the end: ${JSON.stringify(played)}`);
      assert.equal(played.max, expected.disassembly.order.length - 1);
      await shot('played');
      await page.locator('#disassembly-range').fill('0');
      await page.locator('#exploded-range').fill('1');
      assert.equal(await page.getAttribute('#viewport', 'data-exploded'), '1.00');
      await shot('exploded');
      await page.locator('#exploded-range').fill('0');
      // Another Test choice checks the same files again.
      await page.selectOption('#method-select', 'lp');
      const again = await waitForReady(page, 'part1.stl + 8 more');
      assert.equal(again.verdictCode, core.check({ files: partStls }, { method: 'lp' }).verdict);
    });

    it('one OBJ of nine objects picked: an assembly; one of a single solid is still voxelized', async () => {
      await page.setInputFiles('#file-input', { name: 'k9.obj', mimeType: 'text/plain', buffer: puzzleObj });
      const state = await waitForReady(page, 'k9.obj');
      await shot('obj');
      assert.equal(state.verdictCode, 'interlocking');
      // The parts keep their objects' names, in the parts list.
      const details = await page.evaluate(() => [...document.querySelectorAll('#part-list .part-detail')].map((item) => item.textContent));
      assert.deepEqual(details, Array.from({ length: 9 }, (unused, k) => `part${k + 1}`));
      assert.equal(state.key, '1');
      assert.equal(state.meshes, '9');
      // Design says plainly that a mesh assembly is checked, not designed, and keeps its input;
      // Export greys every format and says why.
      const panels = await page.evaluate(() => ({
        note: document.querySelector('#design-mesh-note')?.hidden === false
          ? document.querySelector('#design-mesh-note').textContent : null,
        input: document.querySelector('#design-input').dataset.name,
        formats: [...document.querySelectorAll('#export-format option')].filter((option) => !option.disabled).map((option) => option.value),
        button: document.querySelector('#export-button').disabled,
        why: document.querySelector('#export-unavailable').hidden ? null : document.querySelector('#export-unavailable').textContent,
      }));
      assert.match(panels.note ?? '', /^k9\.obj is a mesh assembly: desia checks it \(verdict, key, disassembly\) but does not design from it/);
      assert.equal(panels.input, 'Cube_4x4x4_origin.puz', 'Design keeps the input it had');
      assert.deepEqual(panels.formats, [], 'no export format is offered');
      assert.equal(panels.button, true);
      assert.match(panels.why ?? '', /^Nothing to export for a mesh assembly: its own OBJ, STL or 3MF files are already the parts/);
      await page.locator('#design-panel').scrollIntoViewIfNeeded();
      await shot('obj-design');
      await page.locator('#export-panel').scrollIntoViewIfNeeded();
      await shot('obj-export');
      await page.evaluate(() => window.scrollTo(0, 0));
      const single = Buffer.from(core.exportAssembly(puzzle, { format: 'obj', part: 1 }));
      await page.setInputFiles('#file-input', { name: 'key.obj', mimeType: 'text/plain', buffer: single });
      await waitForReady(page, 'key_r32.json');
      assert.equal(await page.evaluate(() => document.body.dataset.meshAssembly), '');
      assert.equal(await page.evaluate(() => document.querySelector('#design-mesh-note').hidden), true);
    });

    it('a 3MF written by lib3mf: its two build items are the parts', async () => {
      const bytes = readFileSync(WAGON);
      const expected = core.check({ files: [{ name: 'WagonWithWheels.3mf', bytes }] });
      await dropFiles(page, [{ name: 'WagonWithWheels.3mf', bytes }]);
      const state = await waitForReady(page, 'WagonWithWheels.3mf');
      await shot('3mf');
      assert.equal(state.verdictCode, expected.verdict);
      assert.equal(state.meshes, '2');
    });

    it('a round pin in a round hole: the report notes the curved contact, approximated by its facets', async () => {
      const bytes = pinInHoleObj();
      const expected = core.check({ files: [{ name: 'pin.obj', bytes }] });
      assert.deepEqual(expected.mesh.curvedContacts.map(({ parts, facets }) => ({ parts, facets })), [{ parts: [1, 2], facets: 24 }]);
      await dropFiles(page, [{ name: 'pin.obj', bytes }]);
      const state = await waitForSettled(page, 'pin.obj');
      await shot('curved');
      assert.equal(state.verdictCode, 'not-interlocking');
      const reason = await page.evaluate(() => document.querySelector('#reason').textContent);
      assert.match(reason, /Curved contacts, approximated by their planar facets: parts 1 and 2 \(24 facets\)/);
    });

    it('a bad mesh among the files: the core\'s message names the file and line', async () => {
      await dropFiles(page, [partStls[0], { name: 'broken.obj', bytes: Buffer.from('o a\nv 0 0 0\nv 1 0\n') }]);
      const state = await waitForSettled(page, 'part1.stl + 1 more');
      await shot('error');
      assert.equal(state.status, 'error');
      assert.match(state.error, /^broken\.obj:3: vertex has 2 coordinates/);
    });

    it('no page errors', () => {
      assert.deepEqual(errors, []);
    });
  });
}

describe('the drop-in viewer with a mesh assembly', () => {
  let browser;
  let page;

  before(async () => {
    browser = await openBrowser({ viewport: { width: 1400, height: 900 } });
    page = browser.page;
    await page.goto(new URL('/examples/embed.html', browser.server.url).href);
  });

  after(async () => {
    await browser?.close();
  });

  it('draws the parts of mesh files given as `meshes`, with the package\'s verdict', async () => {
    const expected = core.check({ files: partStls });
    const result = await page.evaluate(async (files) => {
      const { mountViewer } = await import('/web/viewer.js');
      const host = document.createElement('div');
      host.id = 'mesh-viewer';
      host.style.width = '600px';
      document.body.prepend(host);
      const viewer = mountViewer(host, {});
      const report = await viewer.load({ meshes: { files: files.map(({ name, content }) => ({ name, bytes: new Uint8Array(content) })) } });
      return { verdict: report.verdict, key: report.key, kind: viewer.document.kind, parts: viewer.document.parts.length, state: host.dataset.state };
    }, partStls.map(({ name, bytes }) => ({ name, content: [...bytes] })));
    assert.deepEqual(result, { verdict: expected.verdict, key: expected.key, kind: 'mesh', parts: 9, state: 'ready' });
    await page.locator('#mesh-viewer').screenshot({ path: path.join(REPO_ROOT, 'test-artifacts/meshes-viewer.png') });
  });

  it('draws a 3MF given as src: its build items are the parts', async () => {
    const result = await page.evaluate(async () => {
      const { mountViewer } = await import('/web/viewer.js');
      const host = document.createElement('div');
      document.body.prepend(host);
      const viewer = mountViewer(host, {});
      const report = await viewer.load({ src: '/tests/data/meshes/WagonWithWheels.3mf' });
      return { kind: report.kind, parts: report.parts, names: report.mesh.partNames };
    });
    assert.deepEqual(result, { kind: 'mesh', parts: 2, names: ['Wagon', 'Wheel 1'] });
  });
});
