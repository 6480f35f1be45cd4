// SPDX-License-Identifier: GPL-3.0-or-later
// The voxel designer in WebAssembly: the same seed gives the same puzzle as the native CLI, the
// result is verified, progress arrives and can stop the search, bad options are DesiaErrors.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, runCli } from './support.mjs';

const core = await loadDesiaModule();
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-design-'));
const shapePath = (name) => path.join(referenceDir, 'input_puz', name);

for (const [name, parts, seed] of [['Cube_4x4x4_origin.puz', 7, 3], ['Cube_4x4x4_origin.puz', 8, 1], ['bunny_origin.puz', 20, 2]]) {
  test(`${name} N=${parts} seed ${seed}: WebAssembly designs the same puzzle as the native CLI`, () => {
    const output = path.join(tmp, `${name}-${parts}-${seed}.puz`);
    const cli = runCli(['design', 'voxel', '--input', shapePath(name), '--parts', String(parts), '--seed', String(seed), '--jobs', '1', '--output', output]);
    assert.equal(cli.status, 0, cli.stderr);
    const result = core.designVoxel(fs.readFileSync(shapePath(name), 'utf8'), { parts, seed, source: name });
    assert.equal(result.status, 'success', result.message);
    assert.equal(result.puz, fs.readFileSync(output, 'utf8'));
    assert.equal(result.verification.interlocking, true);
    assert.equal(result.verification.key, 1);
    assert.deepEqual(result.verification.disassembly.order, Array.from({ length: parts }, (_, k) => k + 1));
    assert.equal(result.document.parts.length, parts);
    // The written puzzle checks out independently, too.
    const recheck = core.check(result.puz, { method: 'both' });
    assert.equal(recheck.interlocking, true);
  });
}

test('progress arrives after every node and returning false cancels', () => {
  const seen = [];
  const result = core.designVoxel(fs.readFileSync(shapePath('Cube_4x4x4_origin.puz'), 'utf8'), {
    parts: 9,
    seed: 1,
    onProgress: (progress) => {
      seen.push(progress);
      return seen.length < 5;
    },
  });
  assert.equal(result.status, 'cancelled');
  assert.equal(result.puz, null);
  assert.equal(seen.length, 5);
  assert.deepEqual(seen.map((p) => p.nodesVisited), [1, 2, 3, 4, 5]);
  for (const p of seen) {
    assert.equal(p.targetParts, 9);
    assert.ok(p.depth >= 2 && p.depth <= p.bestDepth, JSON.stringify(p));
  }
  assert.match(result.message, /^cancelled: the deepest node had \d+ of 9 parts/);
});

test('a node limit ends the search with how far it got', () => {
  // The hollow cube at seed 2 takes a few hundred nodes.
  const result = core.designVoxel(fs.readFileSync(shapePath('Cube_hollow_4x4x4_origin.puz'), 'utf8'), { parts: 7, seed: 2, nodeLimit: 20 });
  assert.equal(result.status, 'limit-reached');
  assert.equal(result.progress.nodesVisited, 20);
  assert.match(result.message, /node limit/);
});

test('impossible requests and bad options are DesiaErrors with the core message', () => {
  const cube = fs.readFileSync(shapePath('Cube_4x4x4_origin.puz'), 'utf8');
  const cases = [
    [{ parts: 2 }, /parts = 2: an interlocking puzzle needs at least 3 parts/],
    [{ parts: 40 }, /parts = 40 is too many for a shape of 64 voxels/],
    [{ parts: 5, rank: 'prettiest' }, /unknown ranking 'prettiest'/],
    [{ parts: 5, colour: 'red' }, /unknown design option 'colour' \(expected parts, seed, candidates, rank, mode, minPartSize, maxPartSize, evenParts, nodeLimit, keyDirection, groups or timeLimit\)$/],
    [{ parts: 5, groups: [[[9, 9, 9]]] }, /groups\[0\]: voxel \[9,9,9\] is not in the shape/],
    [{ parts: 5, keyDirection: 'up' }, /must be \+x, -x, \+y, -y, \+z or -z, got 'up'/],
    [{}, /design option 'parts' is required/],
  ];
  for (const [options, message] of cases) {
    assert.throws(() => core.designVoxel(cube, options), (error) => {
      assert.ok(error instanceof DesiaError, String(error));
      assert.equal(error.code, 'bad-input');
      assert.match(error.message, message);
      return true;
    });
  }
  assert.throws(() => core.designVoxel('3 1 1\n1 0 1\n', { parts: 3 }), /not face-connected/);
});

test('a design session steps forward, browses children, goes back and is disposed', () => {
  const cube = fs.readFileSync(shapePath('Cube_4x4x4_origin.puz'), 'utf8');
  const session = core.designSession(cube, { parts: 5, seed: 1 });
  try {
    assert.deepEqual({ ...session.state(), document: undefined }, { partsPlaced: 1, targetParts: 5, complete: false, document: undefined });
    assert.equal(session.back(), false);
    const children = session.childCount();
    assert.ok(children > 1);
    const preview = session.preview(1);
    session.choose(1);
    assert.deepEqual(session.state().document.voxel.labels, preview.voxel.labels);
    assert.equal(session.back(), true);
    while (!session.state().complete && session.next()) { /* generate the next part */ }
    assert.equal(session.state().complete, true);
    // The same seed's automatic design takes the best child every time here.
    const automatic = core.designVoxel(cube, { parts: 5, seed: 1 });
    assert.equal(automatic.progress.nodesVisited, 4);
    assert.deepEqual(session.state().document.voxel.labels, automatic.document.voxel.labels);
    assert.equal(session.check().interlocking, true);
    assert.throws(() => session.choose(999), (error) => error instanceof DesiaError && /child 999 does not exist/.test(error.message));
  } finally {
    session.dispose();
  }
  assert.throws(() => session.state(), /the session was disposed/);
  assert.throws(() => core.designSession(cube, { parts: 1 }), /needs at least 3 parts/);
});
