// SPDX-License-Identifier: GPL-3.0-or-later
// The two WebAssembly modules (issue 28, docs/architecture.md "Two WebAssembly modules"): the
// package's worker loads the light module (voxels, contacts, meshes) first and the full one the
// first time a plate or frame comes, and the answers are the CLI's, byte for byte. The light
// module on its own refuses plates and frames with code 'kind-not-built' and answers the rest as
// the full one does, except a mesh assembly whose plan needs moves of several parts off any lattice
// (that search is in the full module only).
//
//   DESIA_CLI=build/dev/core/cli/desia node --test tests/node/two_modules.test.mjs
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, root, runCli } from './support.mjs';

const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');
const tablePath = path.join(root, 'examples/plate/table.json');
const table = fs.readFileSync(tablePath, 'utf8');
const frameCube = fs.readFileSync(path.join(root, 'examples/frame/frame_cube.json'), 'utf8');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-modules-'));
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

const notBuilt = (error) => error.name === 'DesiaError' && error.code === 'kind-not-built' && !error.fatal;

test('the worker loads the light module, then the full one for a plate design, which gives the CLI\'s bytes', async () => {
  const planFile = path.join(tmp, 'table-plan.json');
  const cli = runCli(['design', 'plate', '--input', tablePath, '--output', planFile, '--seed', '3']);
  assert.equal(cli.status, 0, cli.stderr);
  const stlFile = path.join(tmp, 'table-plan.stl');
  assert.equal(runCli(['export', planFile, '--format', 'stl', '--output', stlFile]).status, 0);

  const desia = await createDesia();
  try {
    assert.deepEqual(desia.modules(), ['light']);
    const voxel = await desia.check(k9);
    assert.equal(voxel.verdict, 'interlocking');
    assert.deepEqual(desia.modules(), ['light'], 'a voxel puzzle needs only the light module');

    const result = await desia.designPlate(table, { seed: 3 });
    assert.deepEqual(desia.modules(), ['light', 'full']);
    assert.equal(result.status, 'success', result.message);
    assert.equal(JSON.stringify(result.document), JSON.stringify(JSON.parse(fs.readFileSync(planFile, 'utf8'))),
      'the same plan as the CLI');
    const stl = await desia.exportAssembly(result.document, { format: 'stl' });
    assert.deepEqual(Buffer.from(stl), fs.readFileSync(stlFile), 'the same STL bytes as the CLI');

    // From then on the full module answers, voxels too, with the same results.
    assert.deepEqual(await desia.check(k9), voxel);
  } finally {
    await desia.terminate();
  }
});

test('every kind of call about a plate or frame reaches the full module: check, sessions, frames, cut sheets', async () => {
  for (const call of [
    (desia) => desia.check(table),
    (desia) => desia.parseDocument(frameCube),
    (desia) => desia.partSurfaces(table),
    (desia) => desia.parseFrame(frameCube),
    (desia) => desia.designSession(table).then((session) => session.state()),
    (desia) => desia.designFrame(frameCube, { nodeLimit: 1 }),
    (desia) => desia.cutSheets(table).catch((error) => assert.notEqual(error.code, 'kind-not-built')),
  ]) {
    const desia = await createDesia({ worker: false });
    try {
      await call(desia);
      assert.deepEqual(desia.modules(), ['light', 'full'], String(call));
    } finally {
      await desia.terminate();
    }
  }
});

test('modules: \'full\' loads only the full module; a bad value is named', async () => {
  const desia = await createDesia({ modules: 'full' });
  try {
    assert.deepEqual(desia.modules(), ['full']);
    assert.equal((await desia.check(table)).verdict, 'not-interlocking');
    assert.deepEqual(desia.modules(), ['full']);
  } finally {
    await desia.terminate();
  }
  await assert.rejects(createDesia({ modules: 'light' }), (error) => error.code === 'bad-input' && /modules must be 'light-first' or 'full'/.test(error.message));
});

test('the light module alone refuses plates and frames with kind-not-built, and answers the rest as the full one', async () => {
  const light = await loadDesiaModule({ module: 'light' });
  const full = await loadDesiaModule();
  assert.equal(light.module(), 'light');
  assert.equal(full.module(), 'full');
  assert.deepEqual(light.check(k9, { method: 'both' }), full.check(k9, { method: 'both' }));
  assert.deepEqual(Buffer.from(light.exportAssembly(k9, { format: 'stl' })), Buffer.from(full.exportAssembly(k9, { format: 'stl' })));
  assert.deepEqual(light.exportFormats(), full.exportFormats());
  assert.throws(() => light.check(table), notBuilt);
  assert.throws(() => light.parseDocument(frameCube), notBuilt);
  assert.throws(() => light.designPlate(table), notBuilt);
  assert.throws(() => light.designFrame(frameCube), notBuilt);
  assert.throws(() => light.cutSheets(table), notBuilt);
  assert.throws(() => light.designSession(table), notBuilt);
  assert.throws(() => light.exportAssembly(table, { format: 'stl' }), notBuilt);
  // A malformed document is named the same way by both: the light one reads as far as the full one.
  for (const text of ['{"kind": "plate"}', '{"kind": "frame", "parts": []}', '{"kind": "plate", "contactTolerance": -1, "plates": []}']) {
    const message = (module) => {
      try {
        module.check(text);
      } catch (error) {
        return `${error.code}: ${error.message}`;
      }
      return 'no error';
    };
    assert.equal(message(light), message(full), text);
  }
});

// The OBJ with the vertex farthest along each of the eight diagonals (the first in the file where
// several are as far) moved `depth` back along it, as tests/core/mesh_group_search_test.cpp dents a
// puzzle: it then lies on no lattice, and its plan needs the search for moves of several parts.
function dentedObj(obj, depth) {
  const lines = obj.split('\n');
  const vertices = lines.flatMap((line, at) => (line.startsWith('v ') ? [{ at, p: line.slice(2).trim().split(/\s+/).map(Number) }] : []));
  const along = (p, s) => p[0] * s[0] + p[1] * s[1] + p[2] * s[2];
  for (let corner = 0; corner < 8; ++corner) {
    const s = [corner & 1 ? -1 : 1, corner & 2 ? -1 : 1, corner & 4 ? -1 : 1];
    let farthest = vertices[0].p;
    for (const { p } of vertices) if (along(p, s) > along(farthest, s)) farthest = p;
    const dented = farthest.map((value, k) => value - s[k] * depth);
    for (const vertex of vertices.filter(({ p }) => p.every((value, k) => value === farthest[k]))) {
      lines[vertex.at] = `v ${dented.join(' ')}`;
      vertex.p = dented;
    }
  }
  return lines.join('\n');
}

test('a mesh puzzle off any lattice: the light module refuses its search with kind-not-built, the worker asks the full one, which gives the CLI\'s report', async () => {
  const exported = path.join(tmp, 'dracula.obj');
  const puzzle = path.join(root, 'tests/data/burrtools/DraculasDentalDesaster-p0-s0.puz');
  assert.equal(runCli(['export', puzzle, '--format', 'obj', '--output', exported]).status, 0);
  const dentedFile = path.join(tmp, 'dented.obj');
  fs.writeFileSync(dentedFile, dentedObj(fs.readFileSync(exported, 'utf8'), 0.25));
  const cli = runCli(['check', dentedFile, '--json']);
  assert.ok(cli.status === 0 || cli.status === 1, cli.stderr);
  const report = JSON.parse(cli.stdout);
  assert.deepEqual(report.disassembly.level, [3, 5, 17, 6, 4], 'the voxel kind\'s level, off the lattice');
  assert.equal(report.disassembly.levelMinimal, false, 'the dents are slanted: not claimed the fewest');

  const document = { files: [{ name: 'dented.obj', text: fs.readFileSync(dentedFile, 'utf8') }] };
  const light = await loadDesiaModule({ module: 'light' });
  assert.throws(() => light.check(document), (error) => notBuilt(error) && /moves of several parts off a lattice/.test(error.message));
  const desia = await createDesia();
  try {
    assert.deepEqual(await desia.check(document), report);
    assert.deepEqual(desia.modules(), ['light', 'full']);
  } finally {
    await desia.terminate();
  }
});

test('the light module is much smaller than the full one', () => {
  const size = (file) => fs.statSync(path.join(root, 'dist', file)).size;
  assert.ok(size('desia_light.wasm') < 0.75 * size('desia_wasm.wasm'), `${size('desia_light.wasm')} vs ${size('desia_wasm.wasm')} bytes`);
});
