// SPDX-License-Identifier: GPL-3.0-or-later
// The frame designer (issue 9, paper Section 5.3) against the paper's Table 1 (frame structures),
// natively (the CLI, whose own timing covers the design and its verification) and in WebAssembly
// (node, the package's synchronous core, timed around designFrame: design, verification, the
// result document and its check report). Medians of --runs runs (default 3), seed 1.
//
//   node tests/benchmarks/frame_bench.mjs [--runs N]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { loadDesiaModule } from '../../wasm/index.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const cli = process.env.DESIA_CLI ?? path.join(root, 'build/native/core/cli/desia');
const runsArgument = process.argv.indexOf('--runs');
const runs = runsArgument > 0 ? Number(process.argv[runsArgument + 1]) : 3;

// [example file, label, the paper's time (Table 1) or null]
const CASES = [
  ['frame_cube.json', 'FRAME CUBE, 12 beams (Fig. 19)', '0.53 s'],
  ['flower.json', 'FLOWER, 23 curved beams', '4.10 s'],
  ['frame_chair.json', 'FRAME CHAIR, 11 beams (Fig. 20)', '15.66 s'],
  ['scaffold_92.json', 'SCAFFOLD, 92 beams', '26.41 s'],
  ['scaffold_300.json', 'SCAFFOLD, 4x4x4 cells, 300 beams', null],
];

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const format = (seconds) => (seconds < 0.1 ? `${(seconds * 1000).toFixed(1)} ms` : `${seconds.toFixed(2)} s`);

const core = await loadDesiaModule();
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-frame-bench-'));
console.log('| frame | paper | native | WebAssembly (node) | nodes | same document |');
console.log('| --- | ---: | ---: | ---: | ---: | :---: |');
for (const [file, label, paper] of CASES) {
  const input = path.join(root, 'examples/frame', file);
  if (!fs.existsSync(input)) continue;
  const text = fs.readFileSync(input, 'utf8');
  const output = path.join(scratch, 'result.json');
  const native = [];
  const wasm = [];
  let nodes = 0;
  let same = true;
  let failure = '';
  for (let run = 0; run < runs && !failure; run += 1) {
    const result = spawnSync(cli, ['design', 'frame', '--input', input, '--output', output, '--quiet', '--seed', '1'], { encoding: 'utf8' });
    if (result.status !== 0) {
      // A design that fails within the default limits is a row of its own, not the end of the table.
      failure = `native: ${result.stderr.trim().replace(/^desia: [^:]+: /, '')}`;
      break;
    }
    native.push(Number(/ in ([0-9.e-]+) s$/m.exec(result.stdout)[1]));
    const start = performance.now();
    const design = core.designFrame(text, { seed: 1, source: file });
    wasm.push((performance.now() - start) / 1000);
    if (design.status !== 'success' || design.verification.verdict !== 'interlocking') {
      failure = `WebAssembly: ${design.message}`;
      break;
    }
    nodes = design.progress.nodesVisited;
    same &&= JSON.stringify(design.document) === JSON.stringify(JSON.parse(fs.readFileSync(output, 'utf8')));
  }
  if (failure) console.log(`| ${label} | ${paper ?? '—'} | ${failure} | | | |`);
  else console.log(`| ${label} | ${paper ?? '—'} | ${format(median(native))} | ${format(median(wasm))} | ${nodes} | ${same ? 'yes' : 'NO'} |`);
}
fs.rmSync(scratch, { recursive: true, force: true });
console.log(`\nMedians of ${runs} runs, seed 1; native: the CLI's own timing of the design (verified before it is reported); WebAssembly: designFrame in node (design, verification, the result document and its DBG check report). Same document: the WebAssembly result equals the CLI's file.`);
