// SPDX-License-Identifier: GPL-3.0-or-later
// The plate joint planner against the paper's Table 1 (plate structures), natively (the CLI, whose
// own timing covers the planning and its verification) and in WebAssembly (node, the package's
// synchronous core, timed around designPlate). Medians of --runs runs (default 5).
//
//   node tests/benchmarks/plate_bench.mjs [--runs N]   (DESIA_CLI: another native CLI than build/native's)
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { loadDesiaModule } from '../../wasm/index.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const cli = process.env.DESIA_CLI ?? path.join(root, 'build/native/core/cli/desia');
const runsArgument = process.argv.indexOf('--runs');
const runs = runsArgument > 0 ? Number(process.argv[runsArgument + 1]) : 5;

// [example file, label, the paper's time (Table 1) or null, joints: 'cut' (made in the plates and
// verified there), 'milled' (also sliding dovetails) or 'planned' (the paper's graph design alone),
// and optionally joint sizes (designPlate's jointSizes; the CLI's --joint-size family.name=value)]
const CASES = [
  ['table.json', 'TABLE, 6 plates (Fig. 17)', '0.02 s', 'cut'],
  ['table.json', 'TABLE, 6 plates (Fig. 17)', '0.02 s', 'planned'],
  ['table_divider.json', 'TABLE with a divider through its shelf, 7 plates', null, 'cut'],
  ['table_split_side.json', 'TABLE with its left side in two halves, 7 plates (an in-plane dovetail)', null, 'cut'],
  ['bench_2_bays.json', 'TABLE of 2 bays, 10 plates', null, 'cut'],
  ['table_slanted_crossing.json', 'TABLE, tilted shelf crossed by a divider at 60 degrees, 7 plates', null, 'milled'],
  ['long_table_102.json', 'LONG TABLE, 25 bays, 102 plates', '— (largest: 33)', 'cut'],
  ['cabinet.json', 'CABINET, 7 plates, gable roof (Fig. 13)', '0.09 s', 'milled'],
  ['cabinet.json', 'CABINET, 7 plates, gable roof (Fig. 13)', '0.09 s', 'planned'],
  ['chair_repaired.json', 'CHAIR repaired, 10 plates (Fig. 18)', '0.22 s (8 plates)', 'milled'],
  ['chair_repaired.json', 'CHAIR repaired, 10 plates (Fig. 18)', '0.22 s (8 plates)', 'planned'],
  ['bookshelf.json', 'BOOKSHELF, 12 plates (Fig. 1)', '0.30 s', 'milled'],
  ['bookshelf.json', 'BOOKSHELF, 12 plates (Fig. 1)', '0.30 s', 'planned'],
  ['mitred_box.json', 'MITRED BOX, 6 plates, 45-degree contacts', null, 'milled'],
  ['mitred_box.json', 'MITRED BOX, 6 plates, 45-degree contacts', null, 'planned'],
  ['dodecahedron.json', 'DODECAHEDRON, 12 mitred plates', null, 'milled'],
  ['dodecahedron.json', 'DODECAHEDRON, 12 mitred plates', null, 'planned'],
  ['icosahedron.json', 'ICOSAHEDRON, 20 mitred plates, 41.8-degree planes (step tenons)', null, 'milled'],
  ['leaning_box.json', 'LEANING BOX, 5 plates, sides leaning out 15 degrees (2 slanted dovetails)', null, 'milled'],
  ['leaning_box.json', 'LEANING BOX without slanted dovetails (a slanted tenon)', null, 'milled', { slantedDovetail: { leastDegrees: 89 } }],
  ['slanted_box.json', 'SLANTED BOX, 6 mitred plates, sides leaning out 55 degrees (a mitre slide, a step tenon)', null, 'milled'],
  ['lizard.json', 'LIZARD, 38 mitred plates (Fig. 1: 33)', '2.73 s', 'milled'],
  ['lizard.json', 'LIZARD, 38 mitred plates (Fig. 1: 33)', '2.73 s', 'planned'],
  ['bookcase_123.json', 'BOOKCASE, 123 plates', '— (largest: 33)', 'milled'],
  ['bookcase_123.json', 'BOOKCASE, 123 plates', '— (largest: 33)', 'planned'],
];

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const format = (seconds) => (seconds < 0.1 ? `${(seconds * 1000).toFixed(1)} ms` : `${seconds.toFixed(2)} s`);

const core = await loadDesiaModule();
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-plate-bench-'));
// A first pass designs every case once, untimed for the table: node compiles a WebAssembly
// function with its baseline compiler on first use and optimizes it in the background later, so
// the designs of a fresh module measure the compilers (the TABLE, the first case, took 32 ms per
// design over its first four runs and 12-18 ms after the others had run). Its times are reported
// apart as "first call" (in table order, from a fresh module).
const firstCall = new Map();
// The CLI's flags for a case's joint sizes.
const sizeFlags = (sizes) =>
  Object.entries(sizes ?? {}).flatMap(([family, values]) =>
    Object.entries(values).flatMap(([name, value]) => ['--joint-size', `${family}.${name}=${value}`]));
const caseKey = (file, joints_, sizes) => `${file}:${joints_}:${JSON.stringify(sizes ?? {})}`;
for (const [file, , , joints_, sizes] of CASES) {
  const input = path.join(root, 'examples/plate', file);
  if (!fs.existsSync(input)) continue;
  const start = performance.now();
  core.designPlate(fs.readFileSync(input, 'utf8'), { joints: joints_, jointSizes: sizes });
  firstCall.set(caseKey(file, joints_, sizes), (performance.now() - start) / 1000);
}
console.log('| design | joints | paper | native | WebAssembly (node) | WebAssembly, first call | joints | nodes |');
console.log('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |');
for (const [file, label, paper, joints_, sizes] of CASES) {
  if (!fs.existsSync(path.join(root, 'examples/plate', file))) continue;
  const input = path.join(root, 'examples/plate', file);
  const text = fs.readFileSync(input, 'utf8');
  const native = [];
  const wasm = [];
  let joints = 0;
  let nodes = 0;
  const cold = firstCall.get(caseKey(file, joints_, sizes));
  for (let run = 0; run < runs; run += 1) {
    const result = spawnSync(cli, ['design', 'plate', '--input', input, '--output', path.join(scratch, 'plan.json'), '--quiet', '--joints', joints_, ...sizeFlags(sizes)], { encoding: 'utf8' });
    if (result.status !== 0) throw new Error(`${file}: desia design plate failed: ${result.stderr}`);
    native.push(Number(/ in ([0-9.e-]+) s$/m.exec(result.stdout)[1]));
    const start = performance.now();
    const design = core.designPlate(text, { joints: joints_, jointSizes: sizes });
    wasm.push((performance.now() - start) / 1000);
    if (design.status !== 'success' || design.verification.verdict !== 'interlocking') throw new Error(`${file}: ${design.message}`);
    joints = design.document.joints.length;
    nodes = design.progress.nodesVisited;
  }
  console.log(`| ${label} | ${joints_} | ${paper ?? '—'} | ${format(median(native))} | ${format(median(wasm))} | ${format(cold)} | ${joints} | ${nodes} |`);
}
fs.rmSync(scratch, { recursive: true, force: true });
console.log(`\nMedians of ${runs} runs; native: the CLI's own timing of planning and verification; WebAssembly: designPlate in node (planning, verification, the plan document and its check report) after a first pass that designed every case once; first call: that pass (in table order, from a fresh module).`);
