// SPDX-License-Identifier: GPL-3.0-or-later
// The package's check of puzzles that need parts moved together (issue 27), on BurrTools' example
// puzzles (tests/data/burrtools): the Pelikan burr's level is 98.2.5 and its `steps` are its 108
// `moves`; a six-piece burr starts with a move of several parts; CubeInCage is a partial plan with
// three parts stuck together. The fields are the ones wasm/index.d.ts declares, and every plan is
// replayed voxel by voxel here (a move may not make two parts of one sub-assembly overlap at any
// voxel on its way; a part going out must get past the rest of its sub-assembly), with code that
// shares nothing with the core's planner.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia } from '../../wasm/index.js';
import { root } from './support.mjs';

const burrtools = path.join(root, 'tests/data/burrtools');
const read = (file) => fs.readFileSync(path.join(burrtools, file), 'utf8');
const declarations = fs.readFileSync(path.join(root, 'wasm/index.d.ts'), 'utf8');

const desia = await createDesia();
after(() => desia.terminate());

/** The field names an interface of index.d.ts declares, and which of them are optional. */
function declaredFields(interfaceName) {
  const match = new RegExp(`^export interface ${interfaceName}\\b[^{]*\\{([\\s\\S]*?)^\\}`, 'm').exec(declarations);
  assert.ok(match, `interface ${interfaceName} not found in index.d.ts`);
  const fields = [...match[1].matchAll(/^ {2}(\w+)(\??):/gm)];
  return { all: fields.map((m) => m[1]).sort(), required: fields.filter((m) => !m[2]).map((m) => m[1]).sort() };
}

function assertDeclared(object, interfaceName) {
  const { all, required } = declaredFields(interfaceName);
  for (const key of Object.keys(object)) assert.ok(all.includes(key), `${interfaceName} does not declare ${key}`);
  for (const key of required) assert.ok(key in object, `${interfaceName}.${key} is missing`);
}

/** A step is well formed: ascending part ids of the puzzle, a move along one axis (a unit one when out). */
function assertStep(step, partIds) {
  assertDeclared(step, 'DisassemblyStep');
  assert.ok(step.parts.length >= 1 && step.parts.every((id) => partIds.includes(id)), JSON.stringify(step));
  assert.deepEqual(step.parts, [...step.parts].sort((a, b) => a - b));
  assert.equal(step.move.filter((value) => value !== 0).length, 1, JSON.stringify(step));
  if (step.out) assert.equal(Math.abs(step.move.find((value) => value !== 0)), 1, JSON.stringify(step));
  assert.equal(typeof step.out, 'boolean');
}

/**
 * Replays `steps` on the voxels of `document` one voxel at a time. Returns the sub-assemblies left
 * (arrays of part ids); throws when a move runs a part into another of its sub-assembly.
 */
function replay(document, steps) {
  const [nx, ny, nz] = document.voxel.size;
  const voxels = new Map();
  document.voxel.labels.forEach((label, index) => {
    if (label <= 0) return;
    const x = index % nx;
    const y = Math.floor(index / nx) % ny;
    const z = Math.floor(index / (nx * ny));
    if (!voxels.has(label)) voxels.set(label, []);
    voxels.get(label).push([x, y, z]);
  });
  assert.ok(nz > 0);
  const offsets = new Map([...voxels.keys()].map((id) => [id, [0, 0, 0]]));
  let subAssemblies = [[...voxels.keys()].sort((a, b) => a - b)];
  const key = (id, [x, y, z]) => {
    const [dx, dy, dz] = offsets.get(id);
    return `${x + dx},${y + dy},${z + dz}`;
  };
  const overlap = (group, rest) => {
    const taken = new Set(rest.flatMap((id) => voxels.get(id).map((voxel) => key(id, voxel))));
    return group.some((id) => voxels.get(id).some((voxel) => taken.has(key(id, voxel))));
  };
  const shift = (group, unit) => {
    for (const id of group) offsets.set(id, offsets.get(id).map((value, axis) => value + unit[axis]));
  };
  const extent = (ids, axis, sign) => Math.max(...ids.flatMap((id) => voxels.get(id).map((voxel) => sign * (voxel[axis] + offsets.get(id)[axis]))));
  steps.forEach((step, index) => {
    const sub = subAssemblies.find((candidate) => step.parts.every((id) => candidate.includes(id)));
    assert.ok(sub, `move ${index + 1}: parts ${step.parts} are not in one sub-assembly`);
    const rest = sub.filter((id) => !step.parts.includes(id));
    assert.ok(rest.length > 0, `move ${index + 1}: nothing to move against`);
    const axis = step.move.findIndex((value) => value !== 0);
    const sign = Math.sign(step.move[axis]);
    const unit = [0, 0, 0];
    unit[axis] = sign;
    // Out: until the moved parts' nearest voxel is past the rest's farthest one along the axis.
    const count = step.out ? null : Math.abs(step.move[axis]);
    for (let moved = 0; step.out ? -extent(step.parts, axis, -sign) <= extent(rest, axis, sign) : moved < count; moved += 1) {
      shift(step.parts, unit);
      assert.ok(!overlap(step.parts, rest), `move ${index + 1} (parts ${step.parts}) runs into parts ${rest} after ${moved + 1} voxels`);
    }
    if (step.out) subAssemblies = [...subAssemblies.filter((candidate) => candidate !== sub), step.parts, rest];
  });
  return subAssemblies;
}

test("the Pelikan burr: level 98.2.5, and `steps` are its 108 moves, which replay voxel by voxel", async () => {
  const text = read('PelikanBurr-p0-s0.puz');
  const report = await desia.check(text, { source: 'PelikanBurr-p0-s0.puz' });
  const plan = report.disassembly;
  assert.ok(plan, 'the Pelikan burr comes apart');
  assertDeclared(plan, 'Disassembly');
  assert.equal(plan.level[0], 98);
  assert.deepEqual(plan.level, [98, 2, 5]);
  assert.equal(plan.levelMinimal, true);
  assert.equal(plan.steps.length, plan.moves);
  assert.equal(plan.moves, 108);
  assert.equal(plan.paths, null, 'no single-part plan: parts must move together');
  assert.deepEqual([...plan.order].sort((a, b) => a - b), report.partIds);
  for (const step of plan.steps) assertStep(step, report.partIds);
  assert.ok(plan.steps.some((step) => step.parts.length > 1));
  // Moves before the first separation: the level's first entry counts them, the separation included.
  assert.equal(plan.steps.findIndex((step) => step.out) + 1, plan.level[0]);
  const left = replay(await desia.parseDocument(text), plan.steps);
  assert.ok(left.every((sub) => sub.length === 1), `every part comes free: ${JSON.stringify(left)}`);
});

test('a six-piece burr starts with a move of several parts', async () => {
  const text = read('SolidSixPieceBurrs-p0-s0.puz');
  const report = await desia.check(text, { source: 'SolidSixPieceBurrs-p0-s0.puz' });
  const plan = report.disassembly;
  assertDeclared(plan, 'Disassembly');
  assert.ok(plan.steps[0].parts.length > 1, `first move: ${JSON.stringify(plan.steps[0])}`);
  assert.equal(plan.steps.length, plan.moves);
  assert.equal(plan.paths, null);
  for (const step of plan.steps) assertStep(step, report.partIds);
  const left = replay(await desia.parseDocument(text), plan.steps);
  assert.ok(left.every((sub) => sub.length === 1), JSON.stringify(left));
});

test('CubeInCage: a partial plan, its moves replay and leave exactly the parts named stuck together', async () => {
  const text = read('CubeInCage-p0-s0.puz');
  const report = await desia.check(text, { source: 'CubeInCage-p0-s0.puz' });
  assert.equal(report.disassembly, null);
  const failure = report.disassemblyFailure;
  assertDeclared(failure, 'DisassemblyFailure');
  assert.ok(failure.steps.length > 0);
  assert.ok(failure.unseparated.some((group) => group.length > 1));
  assert.deepEqual(failure.unseparated.flat().sort((a, b) => a - b), [...failure.stuck].sort((a, b) => a - b));
  for (const step of failure.steps) assertStep(step, report.partIds);
  const left = replay(await desia.parseDocument(text), failure.steps);
  const together = left.filter((sub) => sub.length > 1).map((sub) => [...sub].sort((a, b) => a - b));
  assert.deepEqual(together, failure.unseparated.map((group) => [...group].sort((a, b) => a - b)));
});

test("the paper's 9-part cube keeps its single-part plan, and its steps are no more moves than its paths", async () => {
  const text = fs.readFileSync(path.join(root, 'examples/voxel/Cube_4x4x4_K9.puz'), 'utf8');
  const report = await desia.check(text, { source: 'Cube_4x4x4_K9.puz' });
  const plan = report.disassembly;
  assertDeclared(plan, 'Disassembly');
  assert.ok(Array.isArray(plan.paths));
  assert.ok(plan.steps.length >= plan.paths.flat().length, 'the playground plays its paths');
  assert.ok(plan.level.every((moves) => moves >= 1));
  const left = replay(await desia.parseDocument(text), plan.steps);
  assert.ok(left.every((sub) => sub.length === 1));
});
