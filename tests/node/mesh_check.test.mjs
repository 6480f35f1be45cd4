// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check FILE.obj|.stl|.3mf [more files]` (issue 29): a voxel puzzle exported by desia's own
// exporter and read back as meshes gets the puzzle's verdict, key and a complete plan, from one OBJ
// and from one binary STL per part; bad input exits 2 naming the file and line or the part.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { root, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-mesh-'));
const puzzle = path.join(root, 'examples/voxel/Cube_4x4x4_K9.puz');

function exportTo(name, ...options) {
  const file = path.join(tmp, name);
  const result = runCli(['export', puzzle, ...options, '--output', file]);
  assert.equal(result.status, 0, result.stderr);
  return file;
}

test('an exported voxel puzzle read back as one OBJ: interlocking, key 1, every part out', () => {
  const obj = exportTo('k9.obj', '--format', 'obj');
  const text = runCli(['check', obj]);
  assert.equal(text.status, 0, text.stderr);
  assert.match(text.stdout, /^meshes: 9 parts, \d+ triangles, \d+ planar faces, 60 contacts/m);
  assert.match(text.stdout, /^parts: 9 \(mesh\)$/m);
  assert.match(text.stdout, /^key: part 1, free along -z$/m);
  assert.match(text.stdout, /^ {2}part 3: \+z 1 mm, -x 1$/m);
  const json = runCli(['check', obj, '--json', '--method', 'both']);
  assert.equal(json.status, 0, json.stderr);
  const report = JSON.parse(json.stdout);
  assert.equal(report.kind, 'mesh');
  assert.equal(report.verdict, 'interlocking');
  assert.equal(report.key, 1);
  assert.equal(report.mesh.contacts, 60);
  assert.deepEqual(report.disassembly.order.length, 9);
  assert.equal(report.disassembly.paths[7][0].length, 1);  // part 3's first move: 1 mm up
});

test('one binary STL per part, in metres: the same verdict', () => {
  const files = [];
  for (let part = 1; part <= 9; part += 1) {
    files.push(exportTo(`part${part}.stl`, '--format', 'stl', '--part', String(part), '--voxel-size', '0.001'));
  }
  const result = runCli(['check', ...files, '--unit', 'm', '--json']);
  assert.equal(result.status, 0, result.stderr);
  const report = JSON.parse(result.stdout);
  assert.equal(report.parts, 9);
  assert.equal(report.key, 1);
  assert.ok(Math.abs(report.mesh.diagonal - Math.sqrt(48)) < 1e-6);
});

test('--tolerance: faces 0.01 mm apart touch with 0.02, not with the default', () => {
  const gap = path.join(tmp, 'gap.obj');
  const box = (name, z, first) => [`o ${name}`,
    ...[0, 1, 2, 3, 4, 5, 6, 7].map((k) => `v ${10 * (k & 1)} ${10 * ((k >> 1) & 1)} ${z + 10 * ((k >> 2) & 1)}`),
    ...[[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
      .map((f) => `f ${f.map((v) => v + first).join(' ')}`)].join('\n');
  fs.writeFileSync(gap, `${box('low', 0, 1)}\n${box('high', 10.01, 9)}\n`);
  let report = JSON.parse(runCli(['check', gap, '--json']).stdout);
  assert.equal(report.mesh.contacts, 0);
  report = JSON.parse(runCli(['check', gap, '--json', '--tolerance', '0.02']).stdout);
  assert.equal(report.mesh.contacts, 1);
  assert.equal(report.mesh.tolerance, 0.02);
});

test('bad input exits 2 and names the file and line, or the part', () => {
  const short = path.join(tmp, 'short.obj');
  fs.writeFileSync(short, 'o a\nv 0 0 0\nv 1 0\n');
  let result = runCli(['check', short]);
  assert.equal(result.status, 2);
  assert.match(result.stderr, /short\.obj:3/);
  const empty = path.join(tmp, 'empty.stl');
  fs.writeFileSync(empty, '');
  result = runCli(['check', empty]);
  assert.equal(result.status, 2);
  assert.match(result.stderr, /empty\.stl: the file is empty/);
  const open = path.join(tmp, 'open.obj');
  fs.writeFileSync(open, 'o lid\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n');
  result = runCli(['check', open]);
  assert.equal(result.status, 2);
  assert.match(result.stderr, /open\.obj: part 1 \('lid'\): is not closed: the edge from vertex 2/);
  const threeMf = path.join(tmp, 'box.3mf');
  fs.writeFileSync(threeMf, 'PK');
  result = runCli(['check', threeMf]);
  assert.equal(result.status, 2);
  assert.match(result.stderr, /box\.3mf: not a ZIP archive/);
  result = runCli(['check', open, '--unit', 'furlong']);
  assert.equal(result.status, 2);
  assert.match(result.stderr, /unknown unit 'furlong'/);
});

test('a 3MF written by lib3mf: one part per build item, in the model\'s unit whatever --unit says', () => {
  const wagon = path.join(root, 'tests/data/meshes/WagonWithWheels.3mf');
  const inMm = runCli(['check', wagon, '--json']);
  assert.equal(inMm.status, 1, inMm.stderr);  // two parts: not interlocking, and both come out
  const report = JSON.parse(inMm.stdout);
  assert.equal(report.parts, 2);
  assert.deepEqual(report.mesh.partNames, ['Wagon', 'Wheel 1']);
  assert.equal(report.mesh.triangles, 96 + 5 * 56);
  assert.equal(report.disassembly.order.length, 2);
  const inMetres = JSON.parse(runCli(['check', wagon, '--json', '--unit', 'm']).stdout);
  assert.equal(inMetres.mesh.diagonal, report.mesh.diagonal);
});
