// SPDX-License-Identifier: GPL-3.0-or-later
// The WebAssembly side of the interlocking-test benchmarks (paper Section 3.2): loads the
// desia_bench_wasm module (the same workloads.cpp as the native desia_bench) in node, times each
// workload and prints a Markdown table with the paper's figures, the native medians (from
// build/bench/native.json, written by desia_bench) and ours.
//
// usage: node tests/benchmarks/wasm_bench.mjs [--runs=7] [--slow-runs=3] [--module=PATH]
//        [--native=PATH|none] [--json=PATH|none]
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const BUNNY = 'tests/reference/desia/data/result_puz/bunny_15x14x11_K80.puz';
const LEVEL_PUZZLE = 'tests/data/burrtools/PelikanBurr-p0-s0.puz';
// A sample is the mean of as many calls as fit in this time, as a native repetition is
// (Google Benchmark's min time): a single 0.3 ms call is mostly timer and scheduling noise.
const SAMPLE_MS = 100;
const MAX_CALLS_PER_SAMPLE = 10000;
// Warm-up lasts this long: V8 first runs wasm from its baseline compiler and swaps in optimised
// code for hot functions a while later, so a single warm-up call still times the baseline code.
const WARM_UP_MS = 500;

function parseArguments(argv) {
  const options = {
    runs: 7,
    slowRuns: 3,
    module: path.join(root, 'build/wasm/tests/benchmarks/desia_bench_wasm.js'),
    native: path.join(root, 'build/bench/native.json'),
    json: path.join(root, 'build/bench/wasm.json'),
  };
  const names = {
    '--runs': 'runs', '--slow-runs': 'slowRuns', '--module': 'module', '--native': 'native', '--json': 'json',
  };
  for (const arg of argv) {
    const [flag, value] = arg.split(/=(.*)/s);
    const key = names[flag];
    if (!key || value === undefined) {
      throw new Error(`unknown argument ${arg} (see the usage at the top of wasm_bench.mjs)`);
    }
    options[key] = key === 'runs' || key === 'slowRuns' ? Number(value) : value;
  }
  if (!(options.runs >= 1) || !(options.slowRuns >= 1)) throw new Error('--runs and --slow-runs must be at least 1');
  return options;
}

// The module is a CommonJS factory (its build folder has its own package.json saying so). The
// wasm bytes are passed in: Emscripten 3.1.6's loader breaks on node 20's fetch (toolchain.md #3).
async function loadModule(modulePath) {
  if (!fs.existsSync(modulePath)) throw new Error(`${modulePath} not found: run \`bash scripts/build.sh wasm\` first`);
  const createModule = createRequire(import.meta.url)(modulePath);
  return createModule({ wasmBinary: fs.readFileSync(modulePath.replace(/\.js$/, '.wasm')) });
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const middle = Math.floor(sorted.length / 2);
  return sorted.length % 2 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
}

const mean = (values) => values.reduce((a, b) => a + b, 0) / values.length;

// Calls the workload for WARM_UP_MS; returns the time of the last call.
function warmUp(module, workload) {
  let spentMs = 0;
  let lastMs = 0;
  while (spentMs < WARM_UP_MS) {
    [lastMs] = module.run(workload.name, 1);
    spentMs += lastMs;
  }
  return lastMs;
}

// Fast workloads: a warm-up (its last call sizes the samples), then `runs` samples, each the mean
// of a batch of calls. Slow ones (seconds per call): `slowRuns` single calls, no warm-up.
function measure(module, workload, options) {
  if (workload.slow) return { samples: module.run(workload.name, options.slowRuns), callsPerSample: 1 };
  const warmUpMs = warmUp(module, workload);
  const callsPerSample = Math.min(MAX_CALLS_PER_SAMPLE, Math.max(1, Math.round(SAMPLE_MS / Math.max(warmUpMs, 1e-3))));
  const samples = [];
  for (let i = 0; i < options.runs; i += 1) samples.push(mean(module.run(workload.name, callsPerSample)));
  return { samples, callsPerSample };
}

function readNative(file) {
  if (file === 'none' || !fs.existsSync(file)) return null;
  return JSON.parse(fs.readFileSync(file, 'utf8'));
}

function formatMs(ms) {
  if (ms === null || ms === undefined || Number.isNaN(ms)) return '—';
  return `${ms.toFixed(ms < 10 ? 3 : ms < 1000 ? 1 : 0)} ms`;
}

// The paper's time over ours, as "3.1x faster" / "2.0x slower".
function speedUp(paperMs, oursMs) {
  if (paperMs === null || !(oursMs > 0)) return '—';
  const ratio = paperMs / oursMs;
  return ratio >= 1 ? `${ratio.toFixed(1)}x faster` : `${(1 / ratio).toFixed(1)}x slower`;
}

function printTable(workloads, results, native) {
  const nativeByName = new Map((native?.workloads ?? []).map((w) => [w.name, w]));
  const header = native
    ? ['workload', 'paper', 'desia native', 'desia wasm', 'wasm / native', 'speed-up vs paper (wasm)']
    : ['workload', 'paper', 'desia wasm', 'speed-up vs paper'];
  console.log(`\n| ${header.join(' | ')} |`);
  console.log(`| ${header.map((h, i) => (i === 0 || h.startsWith('speed') ? '---' : '---:')).join(' | ')} |`);
  for (const workload of workloads) {
    const ours = median(results.get(workload.name).samples);
    const count = results.get(workload.name).samples.length;
    const wasmCell = `${formatMs(ours)}${workload.slow ? ` (${count} run${count === 1 ? '' : 's'})` : ''}`;
    const cells = [workload.name, formatMs(workload.paperMs)];
    if (native) {
      const nativeMs = nativeByName.get(workload.name)?.medianMs;
      cells.push(formatMs(nativeMs), wasmCell, nativeMs > 0 ? `${(ours / nativeMs).toFixed(2)}x` : '—');
    } else {
      cells.push(wasmCell);
    }
    cells.push(speedUp(workload.paperMs, ours));
    console.log(`| ${cells.join(' | ')} |`);
  }
}

function printNotes(options, native) {
  console.log(`\nwasm: median of ${options.runs} samples after ${WARM_UP_MS / 1000} s of warm-up ` +
    `(each sample the mean of the calls that fit in ${SAMPLE_MS / 1000} s), ` +
    `slow rows ${options.slowRuns} single calls; node ${process.version}, one thread.`);
  if (native) console.log(`native: from ${path.relative(root, options.native)} (${native.machine}).`);
  else console.log('native: no results found; run build/native/tests/benchmarks/desia_bench first to compare.');
  console.log('Paper: an iMac with a 4.2GHz CPU (paper Section 5).');
  console.log('The generated cube is not interlocking: "full work" rows time every step an interlocking verdict needs');
  console.log('(no early exit); "check" is what the DBG test really costs on it.');
}

// The cube must be the very same partition natively and here, or the rows compare nothing.
function checkSameCube(cube, native) {
  if (!native?.cube) return;
  if (native.cube.fingerprint !== cube.fingerprint || native.cube.contacts !== cube.contacts) {
    throw new Error(`the generated cube differs from the native one (fingerprint ${cube.fingerprint.toString(16)} vs ` +
      `${native.cube.fingerprint.toString(16)}): the generator is not deterministic across platforms`);
  }
  console.log('Same generated cube as native (fingerprint and contact count match).');
}

function describe(what, s) {
  return `${what}: ${s.parts} parts, ${s.voxels} voxels, ${s.contacts} contacts (part pair x axis), part sizes ` +
    `${s.smallestPart}..${s.largestPart} voxels, label fingerprint ${s.fingerprint.toString(16)}`;
}

function writeResults(file, workloads, results, stats) {
  if (file === 'none') return;
  fs.mkdirSync(path.dirname(file), { recursive: true });
  const document = {
    target: 'wasm',
    node: process.version,
    cube: {
      parts: stats.cube.parts,
      voxels: stats.cube.voxels,
      contacts: stats.cube.contacts,
      fingerprint: stats.cube.fingerprint,
    },
    workloads: workloads.map((w) => ({
      name: w.name,
      paperMs: w.paperMs,
      medianMs: median(results.get(w.name).samples),
      sampleMs: results.get(w.name).samples,
      callsPerSample: results.get(w.name).callsPerSample,
    })),
  };
  fs.writeFileSync(file, `${JSON.stringify(document, null, 2)}\n`);
  console.log(`WebAssembly results written to ${path.relative(root, file)}`);
}

async function main() {
  const options = parseArguments(process.argv.slice(2));
  const module = await loadModule(path.resolve(options.module));
  const stats = module.prepare(fs.readFileSync(path.join(root, BUNNY), 'utf8'), BUNNY,
    fs.readFileSync(path.join(root, LEVEL_PUZZLE), 'utf8'), LEVEL_PUZZLE);
  console.log(describe('bunny-80', stats.bunny));
  console.log(describe('cube35-1500 (generated)', stats.cube));
  const native = readNative(options.native);
  checkSameCube(stats.cube, native);
  const workloads = module.workloads();
  const results = new Map();
  for (const workload of workloads) {
    process.stdout.write(`running ${workload.name} ... `);
    const result = measure(module, workload, options);
    results.set(workload.name, result);
    console.log(`median ${formatMs(median(result.samples))}`);
  }
  printTable(workloads, results, native);
  printNotes(options, native);
  writeResults(options.json, workloads, results, stats);
}

main().catch((error) => {
  console.error(`wasm_bench: error: ${error.message}`);
  process.exit(1);
});
