// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 10's "all cores" and "part-size control": a portfolio of seeds (the CLI's --jobs on
// threads, the package's designVoxel({ jobs }) on workers) gives exactly the puzzle of a single
// search with the seed that won, which the result names; part size bounds and the even-size mode
// hold natively and in WebAssembly alike (same bytes), and impossible bounds are bad input.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-jobs-'));
const shapePath = (name) => path.join(referenceDir, 'input_puz', name);
const cubeFile = shapePath('Cube_4x4x4_origin.puz');
const hollowFile = shapePath('Cube_hollow_4x4x4_origin.puz');

/** Runs `desia design voxel` on `input`; returns { status, stdout, stderr, puz } (puz: the file written). */
function design(input, output, ...options) {
  const result = runCli(['design', 'voxel', '--input', input, '--output', path.join(tmp, output), ...options]);
  const file = path.join(tmp, output);
  return { ...result, puz: result.status === 0 ? fs.readFileSync(file, 'utf8') : null };
}

function partSizes(puz) {
  const labels = puz.trim().split('\n').slice(1).join(' ').trim().split(/\s+/).map(Number);
  const counts = new Map();
  for (const label of labels) if (label > 0) counts.set(label, (counts.get(label) ?? 0) + 1);
  return [...counts.values()];
}

for (const [file, parts, seed, jobs] of [[cubeFile, 9, 1, 3], [hollowFile, 7, 2, 2]]) {
  test(`design voxel --jobs ${jobs} (${path.basename(file)}, N=${parts}): the winning seed alone gives the same bytes`, () => {
    const portfolio = design(file, `portfolio-${parts}.puz`, '--parts', String(parts), '--seed', String(seed), '--jobs', String(jobs));
    assert.equal(portfolio.status, 0, portfolio.stderr);
    const match = portfolio.stdout.match(/^seed: (\d+) won \(seeds (\d+)-(\d+) on (\d+) threads; --jobs 1 --seed \1 gives this puzzle\)$/m);
    assert.ok(match, portfolio.stdout);
    const winner = Number(match[1]);
    assert.deepEqual([Number(match[2]), Number(match[3]), Number(match[4])], [seed, seed + jobs - 1, jobs]);
    assert.ok(winner >= seed && winner < seed + jobs, portfolio.stdout);
    const alone = design(file, `alone-${parts}.puz`, '--parts', String(parts), '--seed', String(winner), '--jobs', '1');
    assert.equal(alone.status, 0, alone.stderr);
    assert.match(alone.stdout, new RegExp(`^seed: ${winner}$`, 'm'));
    assert.equal(portfolio.puz, alone.puz);
    // The same search: the same message (nodes, backtracks, restarts).
    assert.equal(portfolio.stdout.split('\n')[0].replace(/ in [\d.e-]+ s$/, ''), alone.stdout.split('\n')[0].replace(/ in [\d.e-]+ s$/, ''));
  });
}

test('design voxel --max-part-size / --even-parts: every part within the bounds, the spread reported, verified', () => {
  const bounded = design(cubeFile, 'max11.puz', '--parts', '7', '--seed', '2', '--max-part-size', '11', '--jobs', '1');
  assert.equal(bounded.status, 0, bounded.stderr);
  const sizes = partSizes(bounded.puz);
  assert.equal(sizes.length, 7);
  assert.ok(Math.max(...sizes) <= 11, String(sizes));
  assert.match(bounded.stdout, new RegExp(`^part sizes: min ${Math.min(...sizes)}, max ${Math.max(...sizes)}, mean 9.14286$`, 'm'));
  assert.match(bounded.stdout, /^verdict: interlocking/m);

  const even = design(cubeFile, 'even.puz', '--parts', '8', '--seed', '1', '--even-parts', '--jobs', '1');
  assert.equal(even.status, 0, even.stderr);
  const evenSizes = partSizes(even.puz);
  // 64 / 8 = 8 voxels a part, within max(1, 20%) = 1: 7 to 9.
  assert.ok(Math.min(...evenSizes) >= 7 && Math.max(...evenSizes) <= 9, String(evenSizes));
  assert.match(even.stdout, /^part sizes: min [7-9], max [7-9], mean 8$/m);
});

test('design voxel: impossible part sizes and jobs are exit 2 naming the values', () => {
  const cases = [
    [['--max-part-size', '8', '--min-part-size', '9'], /max part size 8 is less than min part size 9/],
    [['--max-part-size', '5'], /max part size 5 is too small: 7 parts of at most 5 voxels hold 35, fewer than the shape's 64 voxels/],
    [['--min-part-size', '10'], /min part size 10 is too large: 7 parts of at least 10 voxels need 70, more than the shape's 64 voxels/],
    [['--jobs', '0'], /--jobs/],
  ];
  for (const [options, message] of cases) {
    for (const jobs of options.includes('--jobs') ? [[]] : [['--jobs', '1'], ['--jobs', '2']]) {
      const result = design(cubeFile, 'never.puz', '--parts', '7', ...options, ...jobs);
      assert.equal(result.status, 2, `${options} ${jobs}: ${result.stderr}`);
      assert.match(result.stderr, message);
    }
  }
});

const core = await loadDesiaModule();

test('WebAssembly: the same bounded and even designs as the native CLI, with the seed and the size spread', () => {
  const cube = fs.readFileSync(cubeFile, 'utf8');
  for (const [options, flags] of [[{ maxPartSize: 11 }, ['--max-part-size', '11']], [{ evenParts: true }, ['--even-parts']]]) {
    const native = design(cubeFile, 'native.puz', '--parts', '7', '--seed', '3', '--jobs', '1', ...flags);
    assert.equal(native.status, 0, native.stderr);
    const result = core.designVoxel(cube, { parts: 7, seed: 3, ...options });
    assert.equal(result.status, 'success', result.message);
    assert.equal(result.puz, native.puz);
    assert.equal(result.seed, 3);
    const sizes = partSizes(result.puz);
    assert.deepEqual(result.partSizes, { min: Math.min(...sizes), max: Math.max(...sizes), mean: 64 / 7 });
  }
  assert.throws(() => core.designVoxel(cube, { parts: 7, maxPartSize: 5 }),
    (error) => error instanceof DesiaError && error.code === 'bad-input' && /max part size 5 is too small/.test(error.message));
  assert.throws(() => core.designVoxel(cube, { parts: 7, evenParts: 'yes' }), /'evenParts' must be true or false/);
});

test('package: designVoxel({ jobs: 2 }) gives the single-worker puzzle of the seed that won, progress of the best', async () => {
  const desia = await createDesia();
  try {
    const shape = fs.readFileSync(hollowFile, 'utf8');
    const seen = [];
    const portfolio = await desia.designVoxel(shape, { parts: 7, seed: 1, jobs: 2, onProgress: (p) => seen.push(p) });
    assert.equal(portfolio.status, 'success', portfolio.message);
    const workers = Math.min(2, os.availableParallelism());
    assert.ok(portfolio.seed >= 1 && portfolio.seed <= workers, String(portfolio.seed));
    assert.ok(seen.length > 0);
    if (workers > 1) {
      for (const progress of seen) assert.ok([1, 2].includes(progress.seed), JSON.stringify(progress));
    }
    const alone = await desia.designVoxel(shape, { parts: 7, seed: portfolio.seed });
    assert.equal(alone.puz, portfolio.puz);
    assert.equal(alone.message, portfolio.message);
    assert.deepEqual(alone.partSizes, portfolio.partSizes);

    await assert.rejects(desia.designVoxel(shape, { parts: 7, jobs: 0 }), /designVoxel: jobs must be a whole number from 1, got a number \(0\)/);
    await assert.rejects(desia.designVoxel(shape, { parts: 2, jobs: 2 }), /parts = 2: an interlocking puzzle needs at least 3 parts/);
    const controller = new AbortController();
    const aborted = desia.designVoxel(fs.readFileSync(cubeFile, 'utf8'), { parts: 10, jobs: 2, signal: controller.signal,
      onProgress: () => controller.abort() });
    await assert.rejects(aborted, (error) => error.name === 'AbortError');
    // The caller's own worker still answers.
    assert.equal((await desia.check(alone.puz)).interlocking, true);
  } finally {
    await desia.terminate();
  }
});
