// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's inputs and exports in headless Chromium: OBJ and STL meshes (dropped, picked,
// bundled) are voxelized in the worker exactly as `desia voxelize` does natively, the resolution
// slider voxelizes again, broken meshes show the core's message, and a puzzle designed from a
// voxelized mesh is exported as .puz, JSON, STL, OBJ and BurrTools .xmpuzzle, each parsed back
// here (the JSON and .puz by the native CLI).
//
//   node --test tests/browser/io.test.mjs
//
// Needs what playground.test.mjs needs plus the native CLI (bash scripts/build.sh native).
// Screenshots go to test-artifacts/io-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { gunzipSync } from 'node:zlib';
import { loadDesiaModule } from '../../wasm/index.js';
import {
  REPO_ROOT, assertInterlockingWithKey, checkPrerequisites, openBrowser, pageState, screenshot, waitForReady,
  waitForSettled,
} from './support.mjs';

const CLI = path.join(REPO_ROOT, 'build/native/core/cli/desia');
const TORUS = path.join(REPO_ROOT, 'examples/meshes/torus.obj');
const OCTAHEDRON = path.join(REPO_ROOT, 'tests/data/meshes/octahedron.obj');
const CUBE_PUZZLE = 'Cube_4x4x4_K9.puz';
const DESIGN_TIMEOUT_MS = 30_000;

function runCli(args) {
  const result = spawnSync(CLI, args, { encoding: 'utf8', maxBuffer: 64 << 20 });
  if (result.error) throw result.error;
  return result;
}

/** What `desia voxelize` makes of a mesh file: { voxels, grid: "NXxNYxNZ" }. */
async function nativeVoxelization(meshFile, resolution, scratch) {
  const output = path.join(scratch, `native-${path.basename(meshFile)}-${resolution}.json`);
  const result = runCli(['voxelize', '--input', meshFile, '--resolution', String(resolution), '--output', output]);
  assert.equal(result.status, 0, `desia voxelize failed: ${result.stderr}`);
  const document = JSON.parse(await readFile(output, 'utf8'));
  return { voxels: document.parts[0].voxelCount, grid: document.voxel.size.join('x') };
}

/** Vertices and triangles of a small OBJ (v and f lines with plain indices). */
function parseObj(text) {
  const vertices = [];
  const triangles = [];
  for (const line of text.split('\n')) {
    const fields = line.trim().split(/\s+/);
    if (fields[0] === 'v') vertices.push(fields.slice(1, 4).map(Number));
    if (fields[0] === 'f') triangles.push(fields.slice(1, 4).map((field) => Number(field.split('/')[0]) - 1));
  }
  return { vertices, triangles };
}

function binaryStl({ vertices, triangles }) {
  const bytes = Buffer.alloc(84 + 50 * triangles.length);
  bytes.write('desia test: octahedron', 0, 'ascii');
  bytes.writeUInt32LE(triangles.length, 80);
  triangles.forEach((triangle, t) => {
    let offset = 84 + 50 * t + 12; // The normal stays zero: readers recompute it.
    for (const index of triangle) {
      for (const coordinate of vertices[index]) {
        bytes.writeFloatLE(coordinate, offset);
        offset += 4;
      }
    }
  });
  return bytes;
}

function asciiStl({ vertices, triangles }) {
  const lines = ['solid octahedron'];
  for (const triangle of triangles) {
    lines.push('  facet normal 0 0 0', '    outer loop');
    for (const index of triangle) lines.push(`      vertex ${vertices[index].join(' ')}`);
    lines.push('    endloop', '  endfacet');
  }
  lines.push('endsolid octahedron', '');
  return Buffer.from(lines.join('\n'));
}

/** Triangle count of a binary STL, after checking its size is 84 + 50 n bytes. */
function binaryStlTriangles(bytes) {
  assert.ok(bytes.length >= 84, `an STL has at least 84 bytes, got ${bytes.length}`);
  const count = bytes.readUInt32LE(80);
  assert.equal(bytes.length, 84 + 50 * count, 'binary STL size is 84 + 50 n');
  return count;
}

async function meshState(page) {
  return page.evaluate(() => {
    const panel = document.querySelector('#mesh-panel');
    const stats = document.querySelector('#mesh-stats');
    return {
      hidden: panel.hidden,
      state: panel.dataset.state ?? '',
      text: stats.textContent,
      voxels: Number(stats.dataset.voxels || Number.NaN),
      grid: stats.dataset.grid ?? '',
      code: stats.dataset.code ?? '',
      resolution: document.querySelector('#mesh-resolution-number').value,
    };
  });
}

/** Drops a file on the page as a user would (a drop event carrying it). */
async function dropFile(page, name, bytes) {
  const dataTransfer = await page.evaluateHandle(({ fileName, content }) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([new Uint8Array(content)], fileName));
    return transfer;
  }, { fileName: name, content: [...bytes] });
  await page.dispatchEvent('body', 'dragenter', { dataTransfer });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

/** Clicks Export with `format` (and `part`) and returns { name, bytes } of the download. */
async function exportAs(page, format, part = '0') {
  await page.selectOption('#export-format', format);
  if (!(await page.locator('#export-part').isDisabled())) await page.selectOption('#export-part', part);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-button')]);
  const bytes = await readFile(await download.path());
  await page.waitForFunction(() => document.querySelector('#export-panel').dataset.state !== 'working');
  return { name: download.suggestedFilename(), bytes };
}

/** The shapes of a BurrTools file: [{ x, y, z, name, text }], after checking the XML's frame. */
function xmpuzzleShapes(gzipped) {
  assert.deepEqual([...gzipped.subarray(0, 2)], [0x1f, 0x8b], '.xmpuzzle is gzip');
  const xml = gunzipSync(gzipped).toString('utf8');
  assert.match(xml, /^<\?xml version="1\.0"\?>\s*<puzzle version="2">/);
  assert.match(xml, /<gridType type="0"\s*\/>/, 'a cube grid');
  const shapesSection = /<shapes>([\s\S]*?)<\/shapes>/.exec(xml)[1];
  const shapes = [...shapesSection.matchAll(/<voxel\s+([^>]*)>([^<]*)<\/voxel>/g)].map(([, attributes, text]) => {
    const attribute = (key) => new RegExp(`\\b${key}="([^"]*)"`).exec(attributes)?.[1];
    return { x: Number(attribute('x')), y: Number(attribute('y')), z: Number(attribute('z')), type: attribute('type'), name: attribute('name'), text };
  });
  const problem = /<problem\b[\s\S]*?<\/problem>/.exec(xml)?.[0] ?? '';
  const pieces = [...problem.matchAll(/<shape\s+id="(\d+)"\s+count="(\d+)"\s*\/>/g)].map(([, id, count]) => [Number(id), Number(count)]);
  const result = /<result\s+id="(\d+)"/.exec(problem)?.[1];
  return { shapes, pieces, result: Number(result) };
}

/**
 * The BurrTools string of part `label` (0 = every non-empty voxel, the target shape) over the
 * grid, or over the part's bounding box when the piece was cropped to it.
 */
function expectedVoxelString({ size: [nx, ny, nz], labels }, label, box) {
  const inside = (value) => (label === 0 ? value > 0 : value === label);
  const [x0, y0, z0, x1, y1, z1] = box ?? [0, 0, 0, nx - 1, ny - 1, nz - 1];
  let text = '';
  for (let z = z0; z <= z1; z += 1) {
    for (let y = y0; y <= y1; y += 1) {
      for (let x = x0; x <= x1; x += 1) text += inside(labels[x + nx * (y + ny * z)]) ? '#' : '_';
    }
  }
  return text;
}

function boundingBox({ size: [nx, ny, nz], labels }, label) {
  const box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (let z = 0; z < nz; z += 1) {
    for (let y = 0; y < ny; y += 1) {
      for (let x = 0; x < nx; x += 1) {
        if (labels[x + nx * (y + ny * z)] !== label) continue;
        box[0] = Math.min(box[0], x); box[1] = Math.min(box[1], y); box[2] = Math.min(box[2], z);
        box[3] = Math.max(box[3], x); box[4] = Math.max(box[4], y); box[5] = Math.max(box[5], z);
      }
    }
  }
  return box;
}

/** Checks that shape `index` of the file is part `label` of `voxel` (full grid or cropped). */
function assertShapeIsPart(shape, voxel, label) {
  const [nx, ny, nz] = voxel.size;
  assert.equal(shape.type, '0', `shape of part ${label}: type="0"`);
  if (shape.x === nx && shape.y === ny && shape.z === nz) {
    assert.equal(shape.text, expectedVoxelString(voxel, label), `voxels of part ${label} (full grid)`);
    return;
  }
  const box = label === 0 ? null : boundingBox(voxel, label);
  assert.ok(box, `shape ${label} has the grid's size`);
  assert.deepEqual([shape.x, shape.y, shape.z], [box[3] - box[0] + 1, box[4] - box[1] + 1, box[5] - box[2] + 1], `bounding box of part ${label}`);
  assert.equal(shape.text, expectedVoxelString(voxel, label, box), `voxels of part ${label} (cropped)`);
}

/** Every shape of an exported .xmpuzzle against the labels of the same puzzle. */
function assertXmpuzzleMatches(gzipped, voxel, partCount) {
  const { shapes, pieces, result } = xmpuzzleShapes(gzipped);
  assert.equal(shapes.length, partCount + 1, 'the target shape and one shape per part');
  assert.equal(result, 0, 'shape 0 is the result');
  assert.deepEqual(pieces, Array.from({ length: partCount }, (_, i) => [i + 1, 1]), 'each part once in the problem');
  assertShapeIsPart(shapes[0], voxel, 0);
  for (let label = 1; label <= partCount; label += 1) assertShapeIsPart(shapes[label], voxel, label);
}

describe('playground mesh input and exports in headless Chromium', { timeout: 120_000 }, () => {
  let browser;
  let server;
  let page;
  let core;
  let scratch;
  const pageErrors = [];
  const requestedUrls = [];

  before(async () => {
    checkPrerequisites([CUBE_PUZZLE]);
    for (const file of [CLI, TORUS, OCTAHEDRON]) {
      if (!existsSync(file)) throw new Error(`${file} is missing (the CLI: bash scripts/build.sh native)`);
    }
    scratch = await mkdtemp(path.join(os.tmpdir(), 'desia-io-'));
    browser = await openBrowser({ acceptDownloads: true });
    ({ server, page } = browser);
    browser.context.on('request', (request) => requestedUrls.push(request.url()));
    page.on('pageerror', (error) => pageErrors.push(error.message));
    core = await loadDesiaModule();
  });

  after(async () => {
    await browser?.close();
    if (scratch) await rm(scratch, { recursive: true, force: true });
  });

  it('voxelizes the bundled torus like the CLI, and again when the resolution changes', async () => {
    await page.goto(`${server.url}?example=torus.obj&resolution=16`);
    const shape = await waitForReady(page, 'torus_r16.json');
    assert.equal(shape.parts, '1', 'a voxelized mesh is a one-part shape');
    let mesh = await meshState(page);
    assert.equal(mesh.state, 'ready');
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, await nativeVoxelization(TORUS, 16, scratch));
    assert.match(mesh.text, /^512 voxels · grid 16 × 5 × 16 · \d+ ms$/);
    assert.equal(await page.inputValue('#example-select'), 'torus.obj');
    assert.equal(await page.inputValue('#mesh-resolution'), '16');

    await page.fill('#mesh-resolution', '24');
    await waitForReady(page, 'torus_r24.json');
    mesh = await meshState(page);
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, await nativeVoxelization(TORUS, 24, scratch));
    assert.equal(new URLSearchParams(await page.evaluate(() => location.search)).get('resolution'), '24', 'a bundled mesh keeps its resolution in the link');

    // Quick moves: only the last resolution ends up on screen (earlier runs are dropped or cancelled).
    for (const resolution of [40, 56, 72]) await page.fill('#mesh-resolution', String(resolution));
    const state = await waitForReady(page, 'torus_r72.json');
    mesh = await meshState(page);
    assert.equal(mesh.state, 'ready');
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, await nativeVoxelization(TORUS, 72, scratch));
    if (state.webgl === 'on') assert.equal(state.meshes, '1');
    await screenshot(page, 'io-torus');
  });

  it('voxelizes a dropped binary STL and a picked ASCII STL like the CLI', async () => {
    const octahedron = parseObj(await readFile(OCTAHEDRON, 'utf8'));
    const binary = binaryStl(octahedron);
    const ascii = asciiStl(octahedron);
    const binaryFile = path.join(scratch, 'octahedron.stl');
    const asciiFile = path.join(scratch, 'octahedron-ascii.stl');
    await writeFile(binaryFile, binary);
    await writeFile(asciiFile, ascii);

    await page.fill('#mesh-resolution-number', '8');
    await page.press('#mesh-resolution-number', 'Enter');
    await waitForReady(page, 'torus_r8.json');

    await dropFile(page, 'octahedron.stl', binary);
    await waitForReady(page, 'octahedron_r8.json');
    let mesh = await meshState(page);
    const native = await nativeVoxelization(binaryFile, 8, scratch);
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, native);
    assert.deepEqual(native, { voxels: 80, grid: '8x8x8' }, 'the octahedron at 8: 10 voxels per octant');
    assert.equal(new URLSearchParams(await page.evaluate(() => location.search)).get('resolution'), null, "a user's file keeps no resolution in the link");

    await page.setInputFiles('#file-input', { name: 'octahedron-ascii.stl', mimeType: 'model/stl', buffer: ascii });
    await waitForReady(page, 'octahedron-ascii_r8.json');
    mesh = await meshState(page);
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, await nativeVoxelization(asciiFile, 8, scratch));

    await page.fill('#mesh-resolution', '20');
    await waitForReady(page, 'octahedron-ascii_r20.json');
    mesh = await meshState(page);
    assert.deepEqual({ voxels: mesh.voxels, grid: mesh.grid }, await nativeVoxelization(asciiFile, 20, scratch));
  });

  it("shows the core's message for an open mesh and for a grid that is too large", async () => {
    const lines = (await readFile(OCTAHEDRON, 'utf8')).trimEnd().split('\n');
    const open = Buffer.from(`${lines.slice(0, -1).join('\n')}\n`); // One face less: not closed.
    await page.setInputFiles('#file-input', { name: 'open.obj', mimeType: 'text/plain', buffer: open });
    let state = await waitForSettled(page, 'open_r20.json');
    await screenshot(page, 'io-open-mesh');
    assert.equal(state.status, 'error');
    assert.match(state.error, /^open\.obj: the mesh is not closed: edge between vertices \d+ and \d+ belongs to 1 triangle/);
    let mesh = await meshState(page);
    assert.equal(mesh.state, 'error');
    assert.equal(mesh.code, 'bad-input');

    await page.setInputFiles('#file-input', { name: 'octahedron.obj', mimeType: 'text/plain', buffer: await readFile(OCTAHEDRON) });
    await waitForReady(page, 'octahedron_r20.json');
    await page.fill('#mesh-resolution-number', '1024');
    await page.press('#mesh-resolution-number', 'Enter');
    state = await waitForSettled(page, 'octahedron_r1024.json');
    assert.equal(state.status, 'error');
    assert.match(state.error, /^octahedron\.obj: resolution 1024 gives a grid of 1024 x 1024 x 1024 = \d+ voxels, more than the limit of 16777216/);
    mesh = await meshState(page);
    assert.equal(mesh.code, 'too-large');

    await page.fill('#mesh-resolution', '8');
    const recovered = await waitForReady(page, 'octahedron_r8.json');
    assert.equal(recovered.error, '', 'the error box is cleared');
    assert.equal((await meshState(page)).voxels, 80);
  });

  it('exports a bundled puzzle as .xmpuzzle whose pieces are the parts of the .puz', async () => {
    await page.selectOption('#example-select', CUBE_PUZZLE);
    assertInterlockingWithKey(await waitForReady(page, CUBE_PUZZLE), 1);
    assert.equal((await meshState(page)).hidden, true, 'the mesh panel goes with the mesh');
    assert.equal(await page.locator('#export-format option[value="svg"]').isDisabled(), true, 'SVG is for plate structures');

    const exported = await exportAs(page, 'xmpuzzle');
    assert.equal(exported.name, 'Cube_4x4x4_K9.xmpuzzle');
    const original = core.parseDocument(await readFile(path.join(REPO_ROOT, 'examples/voxel', CUBE_PUZZLE), 'utf8'));
    assertXmpuzzleMatches(exported.bytes, original.voxel, 9);
  });

  it('designs a puzzle from the voxelized torus and exports .puz, JSON, STL, OBJ and .xmpuzzle', async () => {
    await page.selectOption('#example-select', 'torus.obj');
    await page.fill('#mesh-resolution', '16');
    await waitForReady(page, 'torus_r16.json');
    await page.fill('#design-parts', '7');
    await page.fill('#design-seed', '1');
    await page.fill('#design-workers', '1');
    await page.click('#design-button');
    await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: DESIGN_TIMEOUT_MS });
    const outcome = await page.evaluate(() => [document.body.dataset.design, document.querySelector('#design-message').textContent]);
    assert.equal(outcome[0], 'success', `design failed: ${outcome[1]}`);
    const designed = await waitForReady(page, 'torus_r16_N7_seed1.puz');
    assertInterlockingWithKey(designed, 1);
    assert.equal(designed.parts, '7');
    await screenshot(page, 'io-torus-design');

    // .puz and JSON: the native CLI reads both back with the page's verdict and key.
    const puz = await exportAs(page, 'puz');
    assert.equal(puz.name, 'torus_r16_N7_seed1.puz');
    const json = await exportAs(page, 'json');
    assert.equal(json.name, 'torus_r16_N7_seed1.json');
    const document = JSON.parse(json.bytes.toString('utf8'));
    assert.equal(document.kind, 'voxel');
    assert.deepEqual(document.voxel.labels, core.parseDocument(puz.bytes.toString('utf8')).voxel.labels, 'JSON and .puz hold the same grid');
    for (const file of [puz, json]) {
      const saved = path.join(scratch, file.name);
      await writeFile(saved, file.bytes);
      const check = runCli(['check', saved, '--json']);
      assert.equal(check.status, 0, `desia check ${file.name}: ${check.stderr}`);
      const report = JSON.parse(check.stdout);
      assert.equal(report.verdict, designed.verdictCode);
      assert.equal(String(report.key), designed.key);
      assert.equal(report.parts, 7);
    }

    // STL, binary: all parts, then part 3 alone (fewer triangles), each 84 + 50 n bytes.
    const stlAll = await exportAs(page, 'stl', '0');
    assert.equal(stlAll.name, 'torus_r16_N7_seed1.stl');
    const allTriangles = binaryStlTriangles(stlAll.bytes);
    assert.ok(allTriangles > 0);
    const stlPart = await exportAs(page, 'stl', '3');
    assert.equal(stlPart.name, 'torus_r16_N7_seed1-part3.stl');
    const partTriangles = binaryStlTriangles(stlPart.bytes);
    assert.ok(partTriangles > 0 && partTriangles < allTriangles, `part 3: ${partTriangles} of ${allTriangles} triangles`);

    // STL, ASCII: as many facets as the binary file of the same part.
    const ascii = await exportAs(page, 'stl-ascii', '3');
    assert.equal(ascii.name, 'torus_r16_N7_seed1-ascii-part3.stl', 'not the name of the binary STL');
    const asciiText = ascii.bytes.toString('utf8');
    assert.match(asciiText, /^solid\b/);
    assert.equal((asciiText.match(/^\s*facet normal\b/gm) ?? []).length, partTriangles);

    // OBJ: one object per part; faces name existing vertices.
    const obj = await exportAs(page, 'obj', '0');
    assert.equal(obj.name, 'torus_r16_N7_seed1.obj');
    const objText = obj.bytes.toString('utf8');
    const objects = objText.match(/^o .+$/gm) ?? [];
    assert.equal(objects.length, 7, 'one object per part');
    const vertexCount = (objText.match(/^v\s/gm) ?? []).length;
    const faceIndices = [...objText.matchAll(/^f\s+(.+)$/gm)].flatMap(([, fields]) => fields.trim().split(/\s+/).map((field) => Number(field.split('/')[0])));
    assert.ok(faceIndices.length > 0);
    assert.ok(faceIndices.every((index) => Number.isInteger(index) && index >= 1 && index <= vertexCount), 'face indices within the vertex list');

    // .xmpuzzle: N + 1 shapes, pieces = the labels of the .puz export.
    const xmpuzzle = await exportAs(page, 'xmpuzzle');
    assert.equal(xmpuzzle.name, 'torus_r16_N7_seed1.xmpuzzle');
    assertXmpuzzleMatches(xmpuzzle.bytes, document.voxel, 7);
    await screenshot(page, 'io-exported');
    assert.equal((await pageState(page)).source, 'torus_r16_N7_seed1.puz', 'exports leave the assembly on screen');
  });

  it('never requests anything outside 127.0.0.1 and throws no page errors', () => {
    const external = requestedUrls.filter((url) => {
      const { protocol, hostname } = new URL(url);
      return !['data:', 'blob:'].includes(protocol) && hostname !== '127.0.0.1';
    });
    assert.deepEqual(external, []);
    assert.deepEqual(pageErrors, []);
  });
});
