// SPDX-License-Identifier: GPL-3.0-or-later
// `check` of a mesh document in the package (issue 29): the same report as `desia check FILES
// --json`, field for field, on real files — desia's own exports of examples (a voxel puzzle as one
// OBJ and as one binary STL per part in metres, BurrTools puzzles, a plate design, a frame result)
// — through the synchronous core and through the worker of createDesia. Errors are JS Errors
// naming the file and line, or the part; partSurfaces of a mesh document gives every part's
// triangles in millimetres.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { requireBuilt, root, runCli } from './support.mjs';

requireBuilt(path.join(root, 'dist/desia_wasm.wasm'), 'scripts/build.sh wasm');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-mesh-package-'));
const desia = await createDesia();
const core = await loadDesiaModule();
after(() => {
  desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

function exportTo(input, name, ...options) {
  const file = path.join(tmp, name);
  const result = runCli(['export', path.join(root, input), ...options, '--output', file]);
  assert.equal(result.status, 0, result.stderr);
  return file;
}

function cliReport(files, ...options) {
  const result = runCli(['check', ...files, '--json', ...options]);
  assert.ok(result.status === 0 || result.status === 1, result.stderr);
  return JSON.parse(result.stdout);
}

/** The mesh document of files on disk: binary files as bytes, text files as text. */
function meshDocument(files, { unit, tolerance, asText = false } = {}) {
  const document = {
    files: files.map((file) => (asText ? { name: path.basename(file), text: fs.readFileSync(file, 'utf8') }
      : { name: path.basename(file), bytes: fs.readFileSync(file) })),
  };
  if (unit) document.unit = unit;
  if (tolerance) document.tolerance = tolerance;
  return document;
}

/** The CLI names files by their path, the package by their name: the same report otherwise. */
function expectSameReport(packageReport, cli, what) {
  assert.deepEqual(packageReport, cli, what);
}

test('an exported voxel puzzle as one OBJ: the same report as the CLI, text or bytes, core or worker', async () => {
  const obj = exportTo('examples/voxel/Cube_4x4x4_K9.puz', 'k9.obj', '--format', 'obj');
  const cli = cliReport([obj], '--method', 'both');
  assert.equal(cli.kind, 'mesh');
  assert.equal(cli.key, 1);
  expectSameReport(core.check(meshDocument([obj], { asText: true }), { method: 'both' }), cli, 'core, text');
  expectSameReport(core.check(meshDocument([obj]), { method: 'both' }), cli, 'core, bytes');
  expectSameReport(await desia.check(meshDocument([obj]), { method: 'both' }), cli, 'worker');
});

test('one binary STL per part in metres, and a tolerance: the same report as the CLI', async () => {
  const files = [];
  for (let part = 1; part <= 9; part += 1) {
    files.push(exportTo('examples/voxel/Cube_4x4x4_K9.puz', `part${part}.stl`, '--format', 'stl', '--part', String(part),
      '--voxel-size', '0.001'));
  }
  const cli = cliReport(files, '--unit', 'm', '--tolerance', '0.001');
  assert.equal(cli.parts, 9);
  assert.equal(cli.mesh.tolerance, 0.001);
  expectSameReport(await desia.check(meshDocument(files, { unit: 'm', tolerance: 0.001 })), cli, 'nine STL files');
});

test('BurrTools puzzles, a plate design and a frame result exported as OBJ: the same reports as the CLI', () => {
  const inputs = ['tests/data/burrtools/AlPackino-p0-s0.puz', 'tests/data/burrtools/PelikanBurr-p0-s0.puz',
    'tests/data/burrtools/SolidSixPieceBurrs-p0-s0.puz', 'tests/data/burrtools/SolidSixPieceBurrs-p0-s1.puz',
    'examples/plate/table.json', 'examples/frame/frame_cube_result.json'];
  for (const input of inputs) {
    const obj = exportTo(input, `${path.basename(input).replace(/\.[^.]+$/, '')}.obj`, '--format', 'obj');
    const cli = cliReport([obj]);
    assert.equal(cli.kind, 'mesh', input);
    expectSameReport(core.check(meshDocument([obj])), cli, input);
  }
});

test('a 3MF written by lib3mf, with an OBJ beside it: the same report as the CLI', async () => {
  const wagon = path.join(root, 'tests/data/meshes/WagonWithWheels.3mf');
  const crate = path.join(tmp, 'crate.obj');
  const box = (x) => ['o crate', ...[0, 1, 2, 3, 4, 5, 6, 7].map((k) => `v ${x + 10 * (k & 1)} ${10 * ((k >> 1) & 1)} ${10 * ((k >> 2) & 1)}`),
    ...[[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]].map((f) => `f ${f.map((v) => v + 1).join(' ')}`)].join('\n');
  fs.writeFileSync(crate, `${box(-100)}\n`);
  const cli = cliReport([wagon, crate], '--unit', 'inch');
  assert.deepEqual(cli.mesh.partNames, ['Wagon', 'Wheel 1', 'crate']);
  expectSameReport(await desia.check(meshDocument([wagon, crate], { unit: 'inch' })), cli, 'a 3MF and an OBJ in inches');
});

test('bad mesh documents are Errors naming the file and line, or the part', async () => {
  const short = { files: [{ name: 'short.obj', text: 'o a\nv 0 0 0\nv 1 0\n' }] };
  assert.throws(() => core.check(short), (error) => error instanceof Error && error.code === 'bad-input' &&
    /short\.obj:3/.test(error.message));
  await assert.rejects(desia.check(short), (error) => error instanceof DesiaError && /short\.obj:3/.test(error.message));
  const lid = { files: [{ name: 'lid.obj', text: 'o lid\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n' }] };
  assert.throws(() => core.check(lid), /lid\.obj: part 1 \('lid'\): is not closed/);
  assert.throws(() => core.check({ files: [{ name: 'empty.stl', bytes: new Uint8Array() }] }), /empty\.stl: the file is empty/);
  assert.throws(() => core.check({ ...lid, unit: 'furlong' }), /unknown unit 'furlong'/);
  assert.throws(() => core.check({ files: [{ name: 'box.3mf', bytes: new Uint8Array([0x50, 0x4b]) }] }), /box\.3mf: not a ZIP archive/);
  assert.throws(() => core.check({ ...lid, tolerance: -1 }), /contact tolerance/);
  assert.throws(() => core.check({ files: [] }), /needs at least one file/);
  assert.throws(() => core.check({ files: [{ name: 'a.obj' }] }), /files\[0\] \('a\.obj'\) needs either bytes or text/);
  assert.throws(() => core.check({ files: [{ name: 'a.obj', text: 'x' }], units: 'm' }), /unknown mesh document field 'units'/);
});

test('partSurfaces of a mesh document: each part\'s triangles in millimetres, ids as check numbers them', async () => {
  const obj = exportTo('examples/voxel/Cube_4x4x4_K9.puz', 'k9-surfaces.obj', '--format', 'obj');
  const document = meshDocument([obj], { unit: 'inch' });
  const report = core.check(document);
  const surfaces = await desia.partSurfaces(document);
  assert.deepEqual(surfaces.map((surface) => surface.partId), report.partIds);
  assert.equal(surfaces.reduce((sum, surface) => sum + surface.positions.length / 9, 0), report.mesh.triangles);
  let largest = 0;
  for (const surface of surfaces) {
    assert.equal(surface.normals.length, surface.positions.length);
    for (const value of surface.positions) largest = Math.max(largest, Math.abs(value));
  }
  assert.ok(Math.abs(largest - 4 * 25.4) < 1e-3, `the puzzle is 4 inches wide, ${largest} mm`);
});
