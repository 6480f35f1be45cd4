// SPDX-License-Identifier: GPL-3.0-or-later
// The voxel designer in WebAssembly (node), through the package API: the same cases as the native
// desia_design_bench (desia mode), several seeds, success rate and median time beside the paper's;
// --frontier adds issue 10's harder cases, as the native bench does.
//   node tests/benchmarks/wasm_design_bench.mjs [--seeds N] [--time-limit S] [--only TEXT] [--frontier] [--modes desia,recursive]
//     [--module full|light]  (the module: the full one by default; the playground designs voxels in the light one)
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { loadDesiaModule } from '../../wasm/index.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const inputs = path.join(root, 'tests/reference/desia/data/input_puz');

const cases = [
  ['4x4x4 cube, N=7', 'Cube_4x4x4_origin.puz', 7, 0.3],
  ['4x4x4 cube, N=8', 'Cube_4x4x4_origin.puz', 8, 12],
  ['4x4x4 cube, N=9', 'Cube_4x4x4_origin.puz', 9, 1.13 * 3600],
  ['hollow 4x4x4, N=7', 'Cube_hollow_4x4x4_origin.puz', 7, null],
  ['5x5x5 cube, N=16', 'Cube_5x5x5_origin.puz', 16, null],
  ['bunny, N=20', 'bunny_origin.puz', 20, null],
  ['bunny, N=40', 'bunny_origin.puz', 40, null],
  ['bunny, N=80', 'bunny_origin.puz', 80, 0.74 * 3600],
  ['cartoon dog, N=14', 'dog_origin.puz', 14, 23.3],
];
const frontierCases = [
  ['4x4x4 cube, N=10', 'Cube_4x4x4_origin.puz', 10, null],
  ['5x5x5 cube, N=20', 'Cube_5x5x5_origin.puz', 20, null],
  ['6x6x6 cube, N=30', 'generated-cube-6', 30, null],
  ['bunny, N=100', 'bunny_origin.puz', 100, null],
  ['bunny, N=120', 'bunny_origin.puz', 120, null],
];

// A solid cube as .puz text (the native bench's solidCube).
function solidCubePuz(side) {
  const row = Array(side).fill('1').join(' ');
  const layer = Array(side).fill(row).join('\n');
  return `${side} ${side} ${side}\n${Array(side).fill(layer).join('\n\n')}\n`;
}

function option(name, fallback) {
  const index = process.argv.indexOf(name);
  return index >= 0 && index + 1 < process.argv.length ? process.argv[index + 1] : fallback;
}

function seconds(s) {
  if (s === null || s === undefined) return '—';
  if (s < 10) return `${s.toFixed(2)} s`;
  if (s < 3600) return `${s.toFixed(0)} s`;
  return `${(s / 3600).toFixed(2)} h`;
}

const seeds = Number(option('--seeds', 3));
const timeLimit = Number(option('--time-limit', 60));
const only = option('--only', '');
const core = await loadDesiaModule({ module: option('--module', 'full') });
const modes = option('--modes', 'desia,recursive').split(',');
console.log(`Voxel designer in WebAssembly (node ${process.version}, the ${core.module()} module): ${seeds} seeds, ${timeLimit} s limit per run.\n`);
console.log('| case | mode | paper | success | median time (successes) | median nodes | best parts reached |');
console.log('| --- | --- | ---: | ---: | ---: | ---: | ---: |');
const median = (values) => (values.length ? [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)] : null);

// Runs one case in one mode for every seed: successes' times, nodes visited, best depth.
function runCase(shape, parts, mode) {
  const times = [];
  const nodes = [];
  let best = 0;
  for (let seed = 1; seed <= seeds; seed++) {
    const start = performance.now();
    const result = core.designVoxel(shape, { parts, seed, timeLimit, mode });
    const elapsed = (performance.now() - start) / 1000;
    if (result.status === 'success') times.push(elapsed);
    nodes.push(result.progress.nodesVisited);
    best = Math.max(best, result.progress.bestDepth);
  }
  return { times, nodes, best };
}

const frontier = process.argv.includes('--frontier');
for (const [name, file, parts, paper] of frontier ? [...cases, ...frontierCases] : cases) {
  if (only && !name.includes(only)) continue;
  const shape = file === 'generated-cube-6' ? solidCubePuz(6) : fs.readFileSync(path.join(inputs, file), 'utf8');
  for (const mode of modes) {
    const { times, nodes, best } = runCase(shape, parts, mode);
    console.log(`| ${name} | ${mode} | ${seconds(paper)} | ${times.length}/${seeds} | ${seconds(median(times))} | ${median(nodes)} | ${best} of ${parts} |`);
  }
}
