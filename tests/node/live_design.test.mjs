// SPDX-License-Identifier: GPL-3.0-or-later
// Live design (issue 11): designVoxel's, designPlate's and designFrame's progress carries the
// deepest node found so far (`snapshot`) in the synchronous core and through the package's worker;
// snapshots only get deeper, the last one is the result, and a listener does not change the bytes.
// The playground's difficulty line (web/live-design.js) follows docs/benchmarks.md's measured tables.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, loadDesiaModule } from '../../wasm/index.js';
import { createPaceTracker, difficultyText } from '../../web/live-design.js';
import { referenceDir, root } from './support.mjs';

const core = await loadDesiaModule();
const bunnyShape = fs.readFileSync(path.join(referenceDir, 'input_puz/bunny_origin.puz'), 'utf8');
const desia = await createDesia();
after(() => desia.terminate());

/** The snapshot labels a labelling of the shape's cells with parts 1..depth and the remainder. */
function assertVoxelSnapshot(snapshot, shapeLabels) {
  assert.ok(snapshot.labels instanceof Int32Array);
  assert.equal(snapshot.labels.length, shapeLabels.length);
  let maxLabel = 0;
  snapshot.labels.forEach((label, i) => {
    assert.equal(label !== 0, shapeLabels[i] !== 0, `cell ${i}`);
    maxLabel = Math.max(maxLabel, label);
  });
  assert.equal(maxLabel, snapshot.depth + 1, 'parts 1..depth and the remainder');
}

function assertDeeperEachTime(snapshots) {
  assert.ok(snapshots.length > 0, 'snapshots arrived');
  for (let k = 1; k < snapshots.length; k += 1) assert.ok(snapshots[k].depth > snapshots[k - 1].depth, `snapshot ${k}`);
}

test('designVoxel progress carries the deepest node; the bytes are those of a design without a listener', () => {
  const shapeLabels = core.parseDocument(bunnyShape, { source: 'bunny_origin.puz' }).voxel.labels;
  const snapshots = [];
  let progressCalls = 0;
  const live = core.designVoxel(bunnyShape, {
    parts: 20, seed: 2, source: 'bunny_origin.puz',
    onProgress: (progress) => {
      progressCalls += 1;
      if (progress.snapshot) snapshots.push(progress.snapshot);
    },
  });
  const plain = core.designVoxel(bunnyShape, { parts: 20, seed: 2, source: 'bunny_origin.puz' });
  assert.equal(live.status, 'success', live.message);
  assert.equal(live.puz, plain.puz);
  assert.equal(live.message, plain.message);
  assertDeeperEachTime(snapshots);
  for (const snapshot of snapshots) assertVoxelSnapshot(snapshot, shapeLabels);
  // At most one per new depth, not one per node.
  assert.ok(snapshots.length <= 19 && snapshots.length < progressCalls + 1);
  const last = snapshots.at(-1);
  assert.equal(last.depth, 19);
  assert.deepEqual(Array.from(last.labels), live.document.voxel.labels, 'the last snapshot is the puzzle');
});

test('through the package worker, snapshots ride on the throttled progress and the puzzle is the same', async () => {
  const snapshots = [];
  const result = await desia.designVoxel(bunnyShape, {
    parts: 40, seed: 1, source: 'bunny_origin.puz',
    onProgress: (progress) => {
      if (progress.snapshot) snapshots.push(progress.snapshot);
    },
  });
  assert.equal(result.status, 'success', result.message);
  assert.equal(result.puz, core.designVoxel(bunnyShape, { parts: 40, seed: 1, source: 'bunny_origin.puz' }).puz);
  assertDeeperEachTime(snapshots);
  const shapeLabels = core.parseDocument(bunnyShape, { source: 'bunny_origin.puz' }).voxel.labels;
  for (const snapshot of snapshots) assertVoxelSnapshot(snapshot, shapeLabels);
  // The last one before the result is kept for the final progress: the complete puzzle.
  assert.equal(snapshots.at(-1).depth, 39);
});

test('designPlate and designFrame snapshots list the plates or beams placed, the key first', () => {
  const table = fs.readFileSync(path.join(root, 'examples/plate/table.json'), 'utf8');
  const plateSnapshots = [];
  const plan = core.designPlate(table, { source: 'table.json', onProgress: (p) => { if (p.snapshot) plateSnapshots.push(p.snapshot); } });
  assert.equal(plan.status, 'success', plan.message);
  assertDeeperEachTime(plateSnapshots);
  for (const { depth, placed } of plateSnapshots) assert.equal(placed.length, depth);
  assert.equal(plan.message, core.designPlate(table, { source: 'table.json' }).message);

  const scaffold = fs.readFileSync(path.join(root, 'examples/frame/scaffold_92.json'), 'utf8');
  const frameSnapshots = [];
  const frame = core.designFrame(scaffold, { source: 'scaffold_92.json', onProgress: (p) => { if (p.snapshot) frameSnapshots.push(p.snapshot); } });
  assert.equal(frame.status, 'success', frame.message);
  assertDeeperEachTime(frameSnapshots);
  const last = frameSnapshots.at(-1);
  // The deepest node reported before the complete one (the search stops there, with the result).
  assert.ok(last.depth >= 90, `deepest reported ${last.depth} of 91 beams to place`);
  assert.equal(new Set(last.placed).size, last.depth);
  assert.deepEqual(frame.document, core.designFrame(scaffold, { source: 'scaffold_92.json' }).document);
});

test('the difficulty line follows the measured table: below ~6.2 voxels per part is hard', () => {
  assert.match(difficultyText(64, 11), /^~5\.8 voxels per part: hard, designs below ~6\.2 voxels per part take long and may fail$/);
  assert.match(difficultyText(64, 10), /^~6\.4 voxels per part: fine for compact shapes; thin ones \(the bunny\) often fail below ~8$/);
  assert.match(difficultyText(966, 140), /^~6\.9 voxels per part: fine for compact shapes/);
  assert.equal(difficultyText(966, 120), '~8.1 voxels per part: usually succeeds');
  assert.equal(difficultyText(966, 80), '~12 voxels per part: usually succeeds');
  assert.equal(difficultyText(0, 9), '');
});

test('the time estimate follows the pace of the best depth and says when the search backtracks', () => {
  const pace = createPaceTracker();
  const at = (bestDepth, elapsedSeconds) => ({ bestDepth, elapsedSeconds, targetParts: 21 });
  pace.observe(at(1, 0.2));
  assert.equal(pace.estimate(at(1, 0.2), { depthAtEnd: 20 }), '', 'too early');
  pace.observe(at(10, 2));
  assert.equal(pace.estimate(at(10, 2), { depthAtEnd: 20 }), 'about 2 s left at this pace');
  assert.equal(pace.estimate(at(10, 9), { depthAtEnd: 20 }), 'backtracking at 10 of 20 for 7 s');
});
