// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI's contract for frame structures (issue 9): design frame writes a verified result (exit 0)
// that check re-verifies and export turns into meshes, .fpuz and a cut list; a cut-point beam is
// exit 1 naming the beam; bad frames are exit 2 naming joint and beams.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { root, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-frame-cli-'));
const examples = path.join(root, 'examples/frame');

test('design frame: the FRAME CUBE designed (exit 0), same seed same bytes, re-verified by check', () => {
  const result = path.join(tmp, 'cube.json');
  const designed = runCli(['design', 'frame', '--input', path.join(examples, 'frame_cube.json'), '--output', result, '--seed', '3']);
  assert.equal(designed.status, 0, designed.stderr);
  assert.match(designed.stdout, /^verdict: interlocking \(method dbg\)$/m);
  assert.match(designed.stdout, /^removal on the shapes: clear \(each beam, its body and joint voxels, swept along its axis in the planned order\)$/m);
  const document = JSON.parse(fs.readFileSync(result, 'utf8'));
  assert.equal(document.kind, 'frame');
  assert.equal(document.beams.length, 12);
  assert.equal(document.jointVoxels.length, 8);
  assert.ok(document.jointVoxels.every((labels) => labels.length === 27));
  assert.equal(document.removal.length, 11);
  assert.deepEqual(document.removal.map((r) => r.part), Array.from({ length: 11 }, (_, k) => k + 1));
  const again = path.join(tmp, 'cube-again.json');
  assert.equal(runCli(['design', 'frame', '--input', path.join(examples, 'frame_cube.json'), '--output', again, '--seed', '3']).status, 0);
  assert.equal(fs.readFileSync(again, 'utf8'), fs.readFileSync(result, 'utf8'));
  const check = runCli(['check', result, '--json', '--method', 'both']);
  assert.equal(check.status, 0, check.stderr);
  const report = JSON.parse(check.stdout);
  assert.equal(report.verdict, 'interlocking');
  assert.equal(report.key, 1);
  assert.deepEqual(report.keyDirections, ['+y']);
  assert.deepEqual(report.cutPoints, []);
  // The message names the key as the result and check do (beam 1), and the input beam it was.
  const keyInput = document.beams[0].inputId ?? 1;
  const named = keyInput === 1 ? '(key: beam 1)' : `(key: beam 1, input beam ${keyInput})`;
  assert.ok(designed.stdout.startsWith(`designed the joints of 12 beams ${named} in `), designed.stdout.split('\n')[0]);
});

test('check of a frame input names its cut-point beams before any design (cutPoints, as for plates)', () => {
  const cut = runCli(['check', path.join(examples, 'cut_point.json'), '--json']);
  assert.equal(cut.status, 1, cut.stderr);
  const report = JSON.parse(cut.stdout);
  assert.equal(report.kind, 'frame');
  assert.deepEqual(report.cutPoints, [9]);
  const text = runCli(['check', path.join(examples, 'cut_point.json')]);
  assert.match(text.stdout, /^cut points of the parts-graph: beam 9 \(no joints can make this structure interlocking/m);
  for (const name of ['frame_cube.json', 'frame_chair.json', 'flower.json']) {
    const none = runCli(['check', path.join(examples, name), '--json']);
    assert.deepEqual(JSON.parse(none.stdout).cutPoints, [], name);
  }
});

test('export of a frame result: closed STL, OBJ objects per beam, .fpuz that check reads, cut list', () => {
  const result = path.join(tmp, 'chair.json');
  assert.equal(runCli(['design', 'frame', '--input', path.join(examples, 'frame_chair.json'), '--output', result]).status, 0);
  for (const format of ['stl', 'obj', 'fpuz', 'csv']) {
    const out = path.join(tmp, `chair.${format}`);
    const exported = runCli(['export', result, '--format', format, '--output', out]);
    assert.equal(exported.status, 0, exported.stderr);
    assert.ok(fs.statSync(out).size > 0);
  }
  const obj = fs.readFileSync(path.join(tmp, 'chair.obj'), 'utf8');
  assert.equal(obj.match(/^o part\d+$/gm).length, 11);
  const csv = fs.readFileSync(path.join(tmp, 'chair.csv'), 'utf8').trim().split('\n');
  assert.equal(csv.length, 12);
  assert.match(csv[0], /^part,input beam,joint a,face a,joint b,face b,body length/);
  const check = runCli(['check', path.join(tmp, 'chair.fpuz'), '--json']);
  assert.equal(check.status, 0, check.stderr);
  assert.equal(JSON.parse(check.stdout).key, 1);
});

test('design frame: a cut-point beam is exit 1 naming it; bad frames are exit 2 naming joint and beams', () => {
  const cut = runCli(['design', 'frame', '--input', path.join(examples, 'cut_point.json'), '--output', path.join(tmp, 'cut.json')]);
  assert.equal(cut.status, 1);
  assert.match(cut.stderr, /cut_point\.json: beam 9 is a cut point of the parts-graph/);
  const face = path.join(tmp, 'face.json');
  fs.writeFileSync(face, '{"kind":"frame","joints":[[0,0,0],[100,0,0],[100,10,0]],"beams":[[1,2],[1,3],[2,3]]}');
  const bad = runCli(['design', 'frame', '--input', face, '--output', path.join(tmp, 'face-result.json')]);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /face\.json: joint 1: beams 1 and 2 both enter its \+x face/);
  const size = runCli(['design', 'frame', '--input', path.join(examples, 'frame_cube.json'), '--joint-size', 'big', '--output', path.join(tmp, 'x.json')]);
  assert.equal(size.status, 2);
  assert.match(size.stderr, /--joint-size expects a number/);
});
