// SPDX-License-Identifier: GPL-3.0-or-later
// What a page or a node program feels when it uses the npm package (issue 4): the worker-backed
// createDesia's start-up, a check and a design through the worker against the same calls in the
// caller's thread, how fast an AbortSignal stops a long design and how soon the next call runs,
// voxelizing a mesh and exporting a puzzle. Prints a Markdown table of medians.
//
// usage: node tests/benchmarks/package_bench.mjs [--runs=5]
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createDesia } from '../../wasm/index.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const read = (file) => fs.readFileSync(path.join(root, file));
const BUNNY = read('examples/voxel/bunny_15x14x11_K80.puz').toString('utf8');
const CUBE_SHAPE = read('examples/voxel/Cube_4x4x4_origin.puz').toString('utf8');
const BUNNY_SHAPE = read('examples/voxel/bunny_origin.puz').toString('utf8');
const TORUS = read('examples/meshes/torus.obj');

function parseRuns(argv) {
  let runs = 5;
  for (const arg of argv) {
    const match = /^--runs=(\d+)$/.exec(arg);
    if (!match) throw new Error(`unknown argument ${arg} (usage: --runs=N)`);
    runs = Math.max(1, Number(match[1]));
  }
  return runs;
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const middle = Math.floor(sorted.length / 2);
  return sorted.length % 2 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
}

async function timeMs(action) {
  const started = performance.now();
  await action();
  return performance.now() - started;
}

async function medianMs(runs, action) {
  const samples = [];
  for (let run = 0; run < runs; run += 1) samples.push(await timeMs(action));
  return median(samples);
}

/** Starts a long design, aborts it after `afterMs`, and times the rejection and the next call. */
async function abortLatency(desia, afterMs) {
  const controller = new AbortController();
  const running = desia.designVoxel(BUNNY_SHAPE, { parts: 80, seed: 3, timeLimit: 120, signal: controller.signal });
  await new Promise((resolve) => setTimeout(resolve, afterMs));
  const abortedAt = performance.now();
  controller.abort();
  const rejected = await running.then(() => false, (error) => error.name === 'AbortError');
  if (!rejected) throw new Error('the design was not aborted: it ended before the abort');
  const abortMs = performance.now() - abortedAt;
  const nextCallMs = await timeMs(() => desia.check(BUNNY));
  return { abortMs, nextCallMs };
}

async function main() {
  const runs = parseRuns(process.argv.slice(2));
  const rows = [];
  const add = (what, ms, note = '') => rows.push({ what, ms, note });

  add('createDesia() + first check of the 80-part bunny (cold worker)', await medianMs(runs, async () => {
    const desia = await createDesia();
    await desia.check(BUNNY);
    await desia.terminate();
  }));

  const worker = await createDesia();
  const inThread = await createDesia({ worker: false });
  await worker.check(BUNNY);
  await inThread.check(BUNNY);
  add('check, 80-part bunny (DBG + disassembly paths), worker', await medianMs(runs, () => worker.check(BUNNY)));
  add('check, 80-part bunny, in the calling thread', await medianMs(runs, () => inThread.check(BUNNY)));
  const design = { parts: 9, seed: 1, timeLimit: 60 };
  add('design 4x4x4 cube, N=9, seed 1, worker', await medianMs(runs, () => worker.designVoxel(CUBE_SHAPE, design)));
  add('design 4x4x4 cube, N=9, seed 1, in the calling thread',
    await medianMs(runs, () => inThread.designVoxel(CUBE_SHAPE, design)), 'paper: 1.13 h');

  const aborts = [];
  for (let run = 0; run < runs; run += 1) aborts.push(await abortLatency(worker, 1000));
  add('abort a running design (AbortSignal) until the promise rejects', median(aborts.map((a) => a.abortMs)));
  add('next call after an abort (fresh worker + bunny check)', median(aborts.map((a) => a.nextCallMs)));

  for (const resolution of [32, 64]) {
    const document = await worker.voxelize(TORUS, { resolution });
    const voxels = document.voxel.labels.filter((label) => label !== 0).length;
    add(`voxelize torus.obj (576 triangles) at ${resolution}`,
      await medianMs(runs, () => worker.voxelize(TORUS, { resolution })), `${voxels} voxels`);
  }
  for (const format of ['stl', 'obj', 'xmpuzzle']) {
    const bytes = await worker.exportAssembly(BUNNY, { format });
    add(`export the 80-part bunny as ${format}`,
      await medianMs(runs, () => worker.exportAssembly(BUNNY, { format })), `${(bytes.length / 1024).toFixed(0)} KiB`);
  }
  await worker.terminate();
  await inThread.terminate();

  console.log(`| package call (node ${process.version}, median of ${runs}) | ms | note |`);
  console.log('| --- | ---: | --- |');
  for (const { what, ms, note } of rows) console.log(`| ${what} | ${ms.toFixed(1)} | ${note} |`);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
