#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
// Two builds of the CLI side by side on the same designs, in one run: each workload runs old, new,
// old, new, ... (so load on the machine hits both alike), timed as whole processes (wall clock,
// reading and verification included), medians of --runs. For a refactor that must change nothing:
// the outputs must be byte-identical too, and the table says where they are not.
//
//   node scripts/compare-builds.mjs OLD_DESIA NEW_DESIA [--runs N]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../', import.meta.url));
const [oldCli, newCli] = process.argv.slice(2, 4).map((file) => path.resolve(file ?? ''));
const runsAt = process.argv.indexOf('--runs');
const runs = runsAt > 0 ? Number(process.argv[runsAt + 1]) : 5;
if (!fs.existsSync(oldCli) || !fs.existsSync(newCli)) {
  console.error('usage: node scripts/compare-builds.mjs OLD_DESIA NEW_DESIA [--runs N]');
  process.exit(2);
}

const voxel = (shape, parts, seed = 1) => ({
  label: `voxel ${shape} N=${parts} seed ${seed}`,
  args: ['design', 'voxel', '--input', `tests/reference/desia/data/input_puz/${shape}`, '--parts', String(parts), '--seed', String(seed), '--jobs', '1', '--output', 'OUT.puz'],
});
const plate = (file, joints) => ({
  label: `plate ${file} ${joints}`,
  args: ['design', 'plate', '--input', `examples/plate/${file}`, '--joints', joints, '--output', 'OUT.json'],
});
const frame = (file, seed = 1) => ({
  label: `frame ${file} seed ${seed}`,
  args: ['design', 'frame', '--input', `examples/frame/${file}`, '--seed', String(seed), '--output', 'OUT.json'],
});
const check = (file) => ({ label: `check ${path.basename(file)}`, args: ['check', file, '--method', 'both'] });

const WORKLOADS = [
  voxel('Cube_4x4x4_origin.puz', 9), voxel('Cube_5x5x5_origin.puz', 16), voxel('Cube_hollow_4x4x4_origin.puz', 7),
  voxel('bunny_origin.puz', 40), voxel('dog_origin.puz', 14),
  plate('table.json', 'cut'), plate('long_table_102.json', 'cut'), plate('cabinet.json', 'milled'),
  plate('bookshelf.json', 'milled'), plate('lizard.json', 'milled'), plate('bookcase_123.json', 'milled'),
  plate('bookcase_123.json', 'planned'),
  frame('frame_cube.json'), frame('flower.json'), frame('scaffold_92.json'), frame('scaffold_300.json'), frame('scaffold_882.json'),
  check('tests/reference/desia/data/result_puz/bunny_15x14x11_K80.puz'),
  // The complete disassembler (levels of 98 and 3.5.17: group moves, the gap matrix).
  check('tests/data/burrtools/PelikanBurr-p0-s0.puz'), check('tests/data/burrtools/DraculasDentalDesaster-p0-s0.puz'),
];

const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-compare-'));
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const seconds = (value) => (value < 0.1 ? `${(value * 1000).toFixed(1)} ms` : `${value.toFixed(2)} s`);

function runOnce(cli, which, workload) {
  const out = path.join(scratch, `${which}-${path.basename(workload.args.find((a) => a.startsWith('OUT')) ?? 'none')}`);
  const args = workload.args.map((a) => (a.startsWith('OUT') ? out : a));
  const start = process.hrtime.bigint();
  const result = spawnSync(cli, args, { cwd: root, encoding: 'utf8', maxBuffer: 1 << 28 });
  const elapsed = Number(process.hrtime.bigint() - start) / 1e9;
  const bytes = fs.existsSync(out) ? fs.readFileSync(out) : Buffer.from(result.stdout.replace(/ in [0-9.e-]+ s/g, ''));
  if (fs.existsSync(out)) fs.rmSync(out);
  return { elapsed, status: result.status, bytes };
}

console.log(`| workload | old | new | new / old | same output |`);
console.log(`| --- | ---: | ---: | ---: | --- |`);
let oldTotal = 0;
let newTotal = 0;
for (const workload of WORKLOADS) {
  const times = { old: [], new: [] };
  let same = true;
  for (let run = 0; run < runs; run += 1) {
    const a = runOnce(oldCli, 'old', workload);
    const b = runOnce(newCli, 'new', workload);
    times.old.push(a.elapsed);
    times.new.push(b.elapsed);
    same = same && a.status === b.status && a.bytes.equals(b.bytes);
  }
  const [o, n] = [median(times.old), median(times.new)];
  oldTotal += o;
  newTotal += n;
  console.log(`| ${workload.label} | ${seconds(o)} | ${seconds(n)} | ${(n / o).toFixed(2)} | ${same ? 'yes' : 'NO'} |`);
}
console.log(`| **sum of medians** | ${seconds(oldTotal)} | ${seconds(newTotal)} | ${(newTotal / oldTotal).toFixed(2)} | |`);
fs.rmSync(scratch, { recursive: true, force: true });
