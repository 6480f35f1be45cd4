// SPDX-License-Identifier: GPL-3.0-or-later
// "Finish automatically from here" in the package: session.finish() runs the designer's search
// below the session's node, in the synchronous core and in the worker alike, and returns a
// verified design whose first parts are the ones chosen by hand.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, root } from './support.mjs';

const cubeShape = fs.readFileSync(path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz'), 'utf8');
const table = fs.readFileSync(path.join(root, 'examples/plate/table.json'), 'utf8');
const frameCube = fs.readFileSync(path.join(root, 'examples/frame/frame_cube.json'), 'utf8');
const desia = await createDesia();
const core = await loadDesiaModule();
after(() => desia.terminate());

/** Labels 1..placed of `chosen` (a session's document) are the same voxels in `finished`. */
function assertKeepsChosenParts(chosen, finished, placed) {
  chosen.voxel.labels.forEach((label, voxel) => {
    if (label >= 1 && label <= placed) assert.equal(finished.voxel.labels[voxel], label, `voxel ${voxel}`);
  });
}

test('finish from a node three steps in: verified, the chosen parts first, the same bytes in the worker and in a repeat', async () => {
  const options = { parts: 9, seed: 3 };
  const local = core.designSession(cubeShape, options);
  const remote = await desia.designSession(cubeShape, options);
  try {
    for (const child of [1, 2, 0]) {
      local.choose(child);
      await remote.choose(child);
    }
    const chosen = local.state();
    assert.equal(chosen.partsPlaced, 4); // 3 parts and the remainder
    const updates = [];
    const finished = await remote.finish({ timeLimit: 60, onProgress: (progress) => updates.push(progress) });
    assert.equal(finished.status, 'success', finished.message);
    assert.equal(finished.verification.interlocking, true);
    assert.equal(finished.verification.key, 1);
    assert.deepEqual(finished.verification.disassembly.order, [1, 2, 3, 4, 5, 6, 7, 8, 9]);
    assertKeepsChosenParts(chosen.document, finished.document, 3);
    assert.ok(updates.length > 0 && updates.at(-1).nodesVisited === finished.progress.nodesVisited);
    // Same path, same seed: the same puzzle, byte for byte, wherever and however often it runs.
    const again = local.finish({ timeLimit: 60 });
    assert.equal(again.puz, finished.puz);
    assert.equal((await remote.finish({ timeLimit: 60 })).puz, finished.puz);
    // The session has not moved.
    assert.deepEqual((await remote.state()).document, chosen.document);
  } finally {
    local.dispose();
    await remote.dispose();
  }
});

test('finish stops at a node limit and refuses bad options, named', async () => {
  const session = core.designSession(cubeShape, { parts: 9, seed: 3 });
  try {
    const stopped = session.finish({ nodeLimit: 1 });
    assert.equal(stopped.status, 'limit-reached');
    assert.equal(stopped.puz, null);
    assert.throws(() => session.finish({ depth: 3 }), (error) => error instanceof DesiaError && error.code === 'bad-input'
      && /unknown finish option 'depth'/.test(error.message));
    assert.throws(() => session.finish({ timeLimit: -1 }), /finish option 'timeLimit' must be seconds >= 0/);
  } finally {
    session.dispose();
  }
  const remote = await desia.designSession(cubeShape, { parts: 9, seed: 3 });
  await assert.rejects(remote.finish({ depth: 3 }), (error) => error.code === 'bad-input' && /unknown option 'depth'/.test(error.message));
  await remote.dispose();
});

test('a frame session finishes from two steps in: verified, the same document in the worker and the core', async () => {
  const options = { seed: 1, source: 'frame_cube.json' };
  const local = core.designSession(frameCube, options);
  const remote = await desia.designSession(frameCube, options);
  try {
    for (const child of [1, 0]) {
      local.choose(child);
      await remote.choose(child);
    }
    const chosen = local.state();
    assert.equal(chosen.steps.length, 2);
    const finished = await remote.finish({ nodeLimit: 200000 });
    assert.equal(finished.status, 'success', finished.message);
    assert.equal(finished.verification.interlocking, true);
    assert.deepEqual(local.finish({ nodeLimit: 200000 }), finished);
    assert.deepEqual((await remote.state()).steps, chosen.steps, 'the session has not moved');
  } finally {
    local.dispose();
    await remote.dispose();
  }
});

test('a plate session finishes from two steps in: verified, the chosen plates first, the same document in the worker and the core', async () => {
  const options = { seed: 1 };
  const local = core.designSession(table, options);
  const remote = await desia.designSession(table, options);
  try {
    for (const child of [0, 1]) {
      local.choose(child);
      await remote.choose(child);
    }
    const chosen = local.state();
    assert.equal(chosen.steps.length, 2);
    const updates = [];
    const finished = await remote.finish({ nodeLimit: 200000, onProgress: (progress) => updates.push(progress) });
    assert.equal(finished.status, 'success', finished.message);
    assert.equal(finished.verification.interlocking, true);
    assert.equal(finished.verification.key, 1);
    // The plan's plates are in removal order, each with its input id: the chosen ones first.
    chosen.steps.forEach((step, k) => {
      assert.equal(finished.document.plates[k].inputId, step.plate, `plate ${k + 1}`);
      assert.deepEqual(finished.document.removal[k], { part: k + 1, direction: step.direction }, `direction ${k + 1}`);
    });
    assert.ok(updates.length > 0 && updates.at(-1).nodesVisited === finished.progress.nodesVisited);
    // Same path, same seed: the same document, in the synchronous core and again in the worker.
    assert.deepEqual(local.finish({ nodeLimit: 200000 }), finished);
    assert.deepEqual(await remote.finish({ nodeLimit: 200000 }), finished);
    assert.deepEqual((await remote.state()).steps, chosen.steps, 'the session has not moved');
    assert.equal(local.finish({ nodeLimit: 1 }).status, 'limit-reached');
  } finally {
    local.dispose();
    await remote.dispose();
  }
});
