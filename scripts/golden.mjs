#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
// The golden corpus (issue 25): what desia produces today for every example, byte for byte, so a
// refactor of the core can be shown to change nothing a user sees.
//
//   node scripts/golden.mjs generate [--only TEXT] [--jobs N]   writes tests/golden/
//   node scripts/golden.mjs compare  [--only TEXT] [--jobs N] [--native | --wasm]
//                                                               re-runs, prints every difference, exit 1 on any
//   node scripts/golden.mjs list                                 the cases, one per line
//
// Natively every case runs the CLI (build/native/core/cli/desia, or DESIA_CLI) from the repository
// root with paths relative to it and pins: the exit code, stdout and stderr (the seconds of
// "... in 0.0123 s" masked as "in <T> s", the temporary output folder as $OUT), every file the
// command wrote (stored when under 200 KiB, else its size and sha256), and `desia check FILE
// --json` of each written result (plates also `--method both`). `compare --wasm` designs the same
// inputs with the same seeds and limits through the package (wasm/index.js, loadDesiaModule; or
// the package folder named by DESIA_PACKAGE) and holds its results against those files; see
// tests/golden/README.md for what exactly is compared. Searches are bounded by --node-limit, never
// by time (the time limits are set out of reach), so no result depends on the machine's speed.
import { spawn } from 'node:child_process';
import crypto from 'node:crypto';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const root = fileURLToPath(new URL('../', import.meta.url));
export const goldenDir = path.join(root, 'tests/golden');
export const casesDir = path.join(goldenDir, 'cases');
export const defaultCli = process.env.DESIA_CLI ? path.resolve(process.env.DESIA_CLI) : path.join(root, 'build/native/core/cli/desia');
/** Files up to this size are stored in the corpus; larger ones are pinned by size and sha256. */
export const STORE_LIMIT = 200 * 1024;
/** A case that takes longer natively does not belong in the corpus (generate warns). */
export const CASE_BUDGET_SECONDS = 3;

// Search limits: nodes bound every search; the time limits are there only to be out of reach
// (`design plate` accepts 1 to 10,000,000 s; the voxel and frame designers take 0 = none).
const VOXEL_NODE_LIMIT = 200;
const PLATE_NODE_LIMIT = 3000;
const PLATE_TIME_LIMIT = 100000;
const FRAME_NODE_LIMIT = 5000;

// ---------------------------------------------------------------------------------------------
// The cases

const seeds = [1, 2];

function voxelCase(shape, parts, seed, extra = {}) {
  const { variant, output = 'puz', nodeLimit = VOXEL_NODE_LIMIT, wasm = true, ...options } = extra;
  const input = `examples/voxel/${shape}.puz`;
  const args = ['design', 'voxel', '--input', input, '--parts', String(parts), '--seed', String(seed), '--jobs', '1',
    '--node-limit', String(nodeLimit), '--time-limit', '0'];
  const flags = { candidates: '--candidates', rank: '--rank', mode: '--mode', minPartSize: '--min-part-size',
    maxPartSize: '--max-part-size', keyDirection: '--key-direction', groups: '--groups' };
  for (const [name, value] of Object.entries(options)) {
    if (name === 'evenParts') args.push('--even-parts');
    else args.push(flags[name], String(value));
  }
  args.push('--output', `$OUT/result.${output}`);
  const id = `voxel/${shape}-n${parts}-s${seed}${variant ? `-${variant}` : ''}`;
  return { id, kind: 'voxel', input, args, wasm: wasm && { parts, seed, nodeLimit, timeLimit: 0, ...options }, output: `result.${output}` };
}

function plateCase(name, joints, seed, extra = {}) {
  const { variant, nodeLimit = PLATE_NODE_LIMIT, repair = false, wasm = true, ext = 'json', ...options } = extra;
  const input = `examples/plate/${name}.${ext}`;
  const args = ['design', 'plate', '--input', input, '--joints', joints, '--seed', String(seed),
    '--node-limit', String(nodeLimit), '--time-limit', String(PLATE_TIME_LIMIT)];
  const flags = { candidates: '--candidates', clearance: '--clearance', tenonWidth: '--tenon-width', tenonCount: '--tenon-count' };
  for (const [option, value] of Object.entries(options)) args.push(flags[option], String(value));
  if (repair) args.push('--repair', '$OUT/repaired.json');
  args.push('--output', '$OUT/result.json');
  const id = `plate/${name}${ext === 'json' ? '' : `.${ext}`}-${joints}-s${seed}${variant ? `-${variant}` : ''}`;
  return { id, kind: 'plate', input, args, wasm: wasm && { joints, seed, nodeLimit, timeLimit: PLATE_TIME_LIMIT, ...options }, output: 'result.json' };
}

function frameCase(name, seed, extra = {}) {
  const { variant, nodeLimit = FRAME_NODE_LIMIT, wasm = true, ...options } = extra;
  const input = `examples/frame/${name}.json`;
  const args = ['design', 'frame', '--input', input, '--seed', String(seed), '--node-limit', String(nodeLimit), '--time-limit', '0'];
  const flags = { candidates: '--candidates', jointSize: '--joint-size' };
  for (const [option, value] of Object.entries(options)) args.push(flags[option], String(value));
  args.push('--output', '$OUT/result.json');
  const id = `frame/${name}-s${seed}${variant ? `-${variant}` : ''}`;
  return { id, kind: 'frame', input, args, wasm: wasm && { seed, nodeLimit, timeLimit: 0, ...options }, output: 'result.json' };
}

function meshCase(name, thickness) {
  const input = `examples/plate/${name}.obj`;
  return { id: `mesh/${name}-t${thickness}`, kind: 'mesh', input, wasm: false, output: 'result.json',
    args: ['plates-from-mesh', '--input', input, '--thickness', String(thickness), '--output', '$OUT/result.json'] };
}

function voxelizeCase(name, resolution, output) {
  const input = `examples/meshes/${name}.obj`;
  return { id: `voxelize/${name}-r${resolution}-${output}`, kind: 'voxelize', input, wasm: { resolution }, output: `result.${output}`,
    args: ['voxelize', '--input', input, '--resolution', String(resolution), '--output', `$OUT/result.${output}`] };
}

function checkCase(file) {
  const id = `check/${file.replace(/^tests\/reference\/desia\/data\//, 'reference/').replace(/^examples\//, '').replaceAll('/', '-')}`;
  return { id, kind: 'check', input: file, args: ['check', file, '--json'], wasm: true, output: null };
}

function listFiles(folder, test) {
  return fs.readdirSync(path.join(root, folder)).filter(test).sort().map((name) => `${folder}/${name}`);
}

function buildCases() {
  const cases = [];
  // Voxel puzzles: every one-part shape (the *_origin files; the other .puz files are designed
  // puzzles, read as shapes they give the same designs), N per shape as the paper and the
  // README's tables use it, seeds 1 and 2.
  const voxelShapes = [
    ['Cube_4x4x4_origin', [3, 5, 8, 9]],
    ['Cube_hollow_4x4x4_origin', [5, 7]],
    ['Cube_5x5x5_origin', [8, 16]],
    ['bunny_origin', [3, 20, 40]],
    ['dog_origin', [8, 14]],
  ];
  // Skipped for time: the hollow cube N=7 seed 2 runs into the node limit after 3.4 s (the
  // limit's outcome is pinned by the 40-node case below).
  const slowVoxel = new Set(['Cube_hollow_4x4x4_origin 7 2']);
  for (const [shape, partCounts] of voxelShapes) {
    for (const parts of partCounts) {
      for (const seed of seeds) if (!slowVoxel.has(`${shape} ${parts} ${seed}`)) cases.push(voxelCase(shape, parts, seed));
    }
  }
  cases.push(voxelCase('bunny_origin', 80, 1));
  // The designer's options, each once on the 4x4x4 cube (and a designed puzzle read as a shape).
  const cube = 'Cube_4x4x4_origin';
  cases.push(
    voxelCase(cube, 7, 1, { variant: 'json', output: 'json' }),
    voxelCase(cube, 7, 1, { variant: 'recursive', mode: 'recursive' }),
    voxelCase(cube, 7, 1, { variant: 'rank-x', rank: 'x' }),
    voxelCase(cube, 7, 2, { variant: 'rank-minus-z', rank: '-z' }),
    voxelCase(cube, 7, 1, { variant: 'even', evenParts: true }),
    voxelCase(cube, 6, 1, { variant: 'key-x', keyDirection: '+x' }),
    voxelCase(cube, 6, 1, { variant: 'm5', candidates: 5 }),
    voxelCase(cube, 6, 1, { variant: 'sizes-8-14', minPartSize: 8, maxPartSize: 14 }),
    voxelCase(cube, 6, 1, { variant: 'groups', groups: 'tests/golden/inputs/cube_groups.json' }),
    voxelCase('Cube_4x4x4_K9', 5, 1, { variant: 'puzzle-as-shape' }),
    // Outcomes without a puzzle: the node limit, an exhausted search, bad input.
    voxelCase('Cube_hollow_4x4x4_origin', 8, 1, { variant: 'limit40', nodeLimit: 40 }),
    voxelCase('Cube_hollow_4x4x4_origin', 16, 1),
    voxelCase(cube, 40, 1),
  );

  // Plate structures: every design, each joint mode, seeds 1 and 2 (skipped: what takes more
  // than CASE_BUDGET_SECONDS natively, and the cut point's repeats: it is refused before any search).
  // (long_table_102 milled: 2.6 s for seed 1 with its checks, 4 s for seed 2.)
  const slow = new Set(['long_table_102 milled 1', 'long_table_102 milled 2']);
  for (const file of listFiles('examples/plate', (name) => name.endsWith('.json'))) {
    const name = path.basename(file, '.json');
    for (const joints of ['cut', 'milled', 'planned']) {
      for (const seed of seeds) {
        if (slow.has(`${name} ${joints} ${seed}`)) continue;
        if (name === 'chair_cut_point') continue;
        cases.push(plateCase(name, joints, seed));
      }
    }
  }
  cases.push(
    plateCase('chair_cut_point', 'cut', 1, { variant: 'repair', repair: true }),
    plateCase('chair_cut_point', 'milled', 1),
    // The default, auto (issue 26): cut where a plan exists, else milled, else planned.
    plateCase('table', 'auto', 1),
    plateCase('cabinet', 'auto', 1),
    plateCase('icosahedron', 'auto', 1),
    plateCase('chair_cut_point', 'auto', 1),
    plateCase('table', 'cut', 1, { variant: 'clearance', clearance: 0.2 }),
    plateCase('table', 'cut', 1, { variant: 'tenons', tenonCount: 2, tenonWidth: 20 }),
    plateCase('table_divider', 'cut', 1, { variant: 'm5', candidates: 5 }),
    plateCase('long_table_102', 'cut', 1, { variant: 'limit30', nodeLimit: 30 }),
    // A mesh given to design plate as it is: one closed solid is one plate.
    plateCase('cube', 'cut', 1, { ext: 'obj', wasm: false }),
  );
  // plates-from-mesh of the sculptures, at the thickness examples/plate/make_sculptures.py uses.
  for (const [name, thickness] of [['cube', 12], ['dodecahedron', 6], ['icosahedron', 6], ['lizard', 6]]) cases.push(meshCase(name, thickness));

  // Frames: every input (not the *_result.json files), seeds 1 and 2; the 882 beams once.
  for (const file of listFiles('examples/frame', (name) => name.endsWith('.json') && !name.endsWith('_result.json'))) {
    const name = path.basename(file, '.json');
    for (const seed of name === 'scaffold_882' || name === 'cut_point' ? [1] : seeds) cases.push(frameCase(name, seed));
  }
  cases.push(
    frameCase('frame_cube', 11, { variant: 'm3', candidates: 3 }),
    frameCase('frame_cube', 1, { variant: 'joint90', jointSize: 90 }),
    frameCase('flower', 1, { variant: 'limit50', nodeLimit: 50 }),
  );

  // Voxelizing a mesh (the input of a voxel design).
  cases.push(voxelizeCase('torus', 16, 'puz'), voxelizeCase('torus', 32, 'json'));

  // `desia check --json` of every example input and result, and of the reference files.
  const examples = [
    ...listFiles('examples/voxel', (name) => name.endsWith('.puz')),
    ...listFiles('examples/plate', (name) => name.endsWith('.json')),
    ...listFiles('examples/frame', (name) => name.endsWith('.json')),
    ...listFiles('examples/contacts', (name) => name.endsWith('.json')),
  ];
  const reference = ['result_puz', 'input_puz'].flatMap((folder) => listFiles(`tests/reference/desia/data/${folder}`, () => true));
  for (const file of [...examples, ...reference]) cases.push(checkCase(file));
  return cases;
}

export const cases = buildCases();

// ---------------------------------------------------------------------------------------------
// Running a case natively

/** "designed ... in 0.00470361 s" -> "designed ... in <T> s" (the only timing the CLI prints). */
export function maskTiming(text) {
  return text.replace(/ in -?\d[\d.]*(?:e[-+]?\d+)? s$/gm, ' in <T> s');
}

function mask(text, outDir) {
  return maskTiming(text.replaceAll(outDir, '$OUT').replaceAll(root, ''));
}

const sha256 = (bytes) => crypto.createHash('sha256').update(bytes).digest('hex');

/** JSON text with the same keys in the same order and -0 kept apart from 0. */
export function canonicalJson(value) {
  return JSON.stringify(value, (key, v) => (typeof v === 'number' && Object.is(v, -0) ? '-0 (negative zero)' : v), 1);
}

/** A digest of a JSON document's content (keys in order, values as doubles), not of its layout. */
export function documentDigest(value) {
  return sha256(canonicalJson(value));
}

/**
 * A plate document with the order of what has no meaningful order sorted away: each plate's and
 * attached solid's `holes` (plates, fabricationPlates) and the `contacts` list (kept apart from
 * that, contacts with the same a, b and normal differ only in area and region). Used only to tell
 * a difference in order from a difference in content (see KNOWN_WASM_ORDER_DIFFERENCES).
 */
export function orderFree(document) {
  const copy = structuredClone(document);
  const byText = (x, y) => {
    const a = canonicalJson(x);
    const b = canonicalJson(y);
    return a < b ? -1 : a > b ? 1 : 0;
  };
  const sortHoles = (solid) => {
    if (Array.isArray(solid?.holes)) solid.holes.sort(byText);
    for (const attached of Array.isArray(solid?.attached) ? solid.attached : []) sortHoles(attached);
  };
  for (const list of ['plates', 'fabricationPlates']) for (const plate of Array.isArray(copy[list]) ? copy[list] : []) sortHoles(plate);
  if (Array.isArray(copy.contacts)) copy.contacts.sort(byText);
  return copy;
}

/**
 * Cases whose WebAssembly result document may differ from the native one in the order of holes
 * and contacts alone (accepted when equal once orderFree() is applied, and said so). None: such
 * differences (the LONG TABLE 102 cut and the BOOKCASE 123 milled, seeds 1 and 2) came from
 * Clipper's sorts, which broke ties apart in libstdc++ and libc++; both builds now compile Clipper
 * with stable sorts (cmake/Clipper.cmake), so every case must match exactly. Kept for a difference
 * of order that a future platform may bring, named, never silently.
 */
export const KNOWN_WASM_ORDER_DIFFERENCES = new Set([]);

function run(cli, args, cwd) {
  return new Promise((resolve, reject) => {
    const started = performance.now();
    const child = spawn(cli, args, { cwd, stdio: ['ignore', 'pipe', 'pipe'] });
    const out = [];
    const err = [];
    child.stdout.on('data', (chunk) => out.push(chunk));
    child.stderr.on('data', (chunk) => err.push(chunk));
    child.on('error', reject);
    child.on('close', (code, signal) => resolve({
      exit: signal ? `signal ${signal}` : code,
      stdout: Buffer.concat(out).toString('utf8'),
      stderr: Buffer.concat(err).toString('utf8'),
      seconds: (performance.now() - started) / 1000,
    }));
  });
}

function artifact(name, bytes, kind) {
  const entry = { size: bytes.length, sha256: sha256(bytes), stored: bytes.length <= STORE_LIMIT };
  if (/\.json$/.test(name)) {
    try {
      const document = JSON.parse(bytes.toString('utf8'));
      entry.documentSha256 = documentDigest(document);
      if (kind === 'plate' && !name.includes('.check')) entry.orderFreeSha256 = documentDigest(orderFree(document));
    } catch {
      // not JSON after all: pinned by its bytes alone
    }
  }
  return entry;
}

/**
 * Runs one case with the native CLI. Returns { record, files, seconds }: the record as stored in
 * record.json and the bytes of every artifact (written files and check outputs) by name.
 */
export async function runNative(testCase, { cli = defaultCli } = {}) {
  if (!fs.existsSync(cli)) throw new Error(`${cli} is missing: build it first (bash scripts/build.sh native)`);
  const outDir = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-golden-'));
  try {
    const args = testCase.args.map((arg) => arg.replaceAll('$OUT', outDir));
    const files = new Map();
    const main = await run(cli, args, root);
    let seconds = main.seconds;
    const record = {
      id: testCase.id,
      kind: testCase.kind,
      command: ['desia', ...testCase.args].join(' '),
      exit: main.exit,
      stdout: testCase.kind === 'check' ? undefined : mask(main.stdout, outDir),
      stderr: mask(main.stderr, outDir),
      files: {},
      checks: [],
    };
    if (testCase.kind === 'check') {
      files.set('check.json', Buffer.from(mask(main.stdout, outDir)));
    } else {
      for (const name of fs.readdirSync(outDir).sort()) {
        const bytes = fs.readFileSync(path.join(outDir, name));
        files.set(name, bytes);
        if (!/\.(json|puz)$/.test(name)) continue;
        const methods = testCase.kind === 'plate' ? [null, 'both'] : [null];
        for (const method of methods) {
          const checkArgs = ['check', path.join(outDir, name), ...(method ? ['--method', method] : []), '--json'];
          const check = await run(cli, checkArgs, root);
          seconds += check.seconds;
          const output = `${name.replace(/\.(json|puz)$/, '')}.check${method ? `-${method}` : ''}.json`;
          files.set(output, Buffer.from(mask(check.stdout, outDir)));
          record.checks.push({ command: ['desia', 'check', `$OUT/${name}`, ...checkArgs.slice(2)].join(' '), exit: check.exit,
            stderr: mask(check.stderr, outDir), stdout: output });
        }
      }
    }
    for (const [name, bytes] of [...files].sort(([a], [b]) => (a < b ? -1 : 1))) record.files[name] = artifact(name, bytes, testCase.kind);
    return { record, files, seconds };
  } finally {
    fs.rmSync(outDir, { recursive: true, force: true });
  }
}

// ---------------------------------------------------------------------------------------------
// Differences

function clip(line) {
  return line === undefined ? '(no such line: the text ends before)' : JSON.stringify(line.length > 240 ? `${line.slice(0, 240)}…` : line);
}

/** Where two texts first differ, as "line N: expected ..., got ..."; null when equal. */
export function firstDifference(expected, actual) {
  if (expected === actual) return null;
  const a = expected.split('\n');
  const b = actual.split('\n');
  for (let i = 0; i < Math.max(a.length, b.length); i += 1) {
    if (a[i] !== b[i]) return `line ${i + 1} (of ${a.length} expected, ${b.length} got): expected ${clip(a[i])}, got ${clip(b[i])}`;
  }
  return 'the texts differ in their line ends';
}

export function caseDir(testCase) {
  return path.join(casesDir, testCase.id);
}

export function readGolden(testCase) {
  const dir = caseDir(testCase);
  const file = path.join(dir, 'record.json');
  if (!fs.existsSync(file)) return null;
  return { record: JSON.parse(fs.readFileSync(file, 'utf8')), dir };
}

/** The stored files of a case against the sizes and digests in its record.json (edited by hand?). */
function corpusProblems(golden) {
  const problems = [];
  for (const [name, entry] of Object.entries(golden.record.files)) {
    if (!entry.stored) continue;
    const file = path.join(golden.dir, name);
    if (!fs.existsSync(file)) problems.push(`corpus damaged: ${name} is missing from ${path.relative(root, golden.dir)}`);
    else if (sha256(fs.readFileSync(file)) !== entry.sha256) {
      problems.push(`corpus damaged: ${path.relative(root, file)} does not match the sha256 in its record.json (edited by hand? regenerate)`);
    }
  }
  return problems;
}

/** Every difference between a fresh native run and the corpus, one line each; [] when equal. */
export function nativeDifferences(testCase, fresh) {
  const golden = readGolden(testCase);
  if (!golden) return [`no golden record in ${path.relative(root, caseDir(testCase))}: run node scripts/golden.mjs generate`];
  const want = golden.record;
  const got = fresh.record;
  const diffs = corpusProblems(golden);
  const text = (what, a, b) => {
    const d = firstDifference(a ?? '', b ?? '');
    if (d) diffs.push(`${what}: ${d}`);
  };
  if (want.command !== got.command) diffs.push(`command: expected ${want.command}, got ${got.command}`);
  if (want.exit !== got.exit) diffs.push(`exit code: expected ${want.exit}, got ${got.exit}`);
  text('stdout', want.stdout, got.stdout);
  text('stderr', want.stderr, got.stderr);
  const names = new Set([...Object.keys(want.files), ...Object.keys(got.files)]);
  for (const name of [...names].sort()) {
    const a = want.files[name];
    const b = got.files[name];
    if (!a) { diffs.push(`${name}: written now, not in the corpus (${b.size} bytes)`); continue; }
    if (!b) { diffs.push(`${name}: in the corpus (${a.size} bytes), not written now`); continue; }
    if (a.sha256 === b.sha256) continue;
    if (a.stored && fs.existsSync(path.join(golden.dir, name))) {
      text(name, fs.readFileSync(path.join(golden.dir, name), 'utf8'), fresh.files.get(name).toString('utf8'));
    } else {
      diffs.push(`${name}: ${a.size} bytes sha256 ${a.sha256.slice(0, 16)}… expected, got ${b.size} bytes sha256 ${b.sha256.slice(0, 16)}…`
        + (a.documentSha256 && a.documentSha256 === b.documentSha256 ? ' (the same document, laid out differently)' : ''));
    }
  }
  const checks = Math.max(want.checks.length, got.checks.length);
  for (let i = 0; i < checks; i += 1) {
    const a = want.checks[i];
    const b = got.checks[i];
    if (!a || !b || a.command !== b.command) { diffs.push(`check ${i + 1}: expected ${a?.command ?? 'none'}, got ${b?.command ?? 'none'}`); continue; }
    if (a.exit !== b.exit) diffs.push(`${a.command}: exit code expected ${a.exit}, got ${b.exit}`);
    text(`${a.command}: stderr`, a.stderr, b.stderr);
  }
  return diffs;
}

// ---------------------------------------------------------------------------------------------
// WebAssembly

/** The package's loadDesiaModule: ../wasm/index.js, or DESIA_PACKAGE's (a folder with wasm/ and dist/). */
export async function loadWasmCore() {
  const folder = process.env.DESIA_PACKAGE ? path.resolve(process.env.DESIA_PACKAGE) : root;
  const wasmFile = path.join(folder, 'dist/desia_wasm.wasm');
  if (!fs.existsSync(wasmFile)) throw new Error(`${wasmFile} is missing: build it first (bash scripts/build.sh wasm)`);
  const { loadDesiaModule } = await import(pathToFileURL(path.join(folder, 'wasm/index.js')).href);
  return loadDesiaModule();
}

function goldenText(golden, name) {
  return fs.readFileSync(path.join(golden.dir, name), 'utf8');
}

/**
 * A document (from the package) against a pinned JSON file: the same content, key order included.
 * Returns null when equal, else { difference } or, when only the order of holes and contacts
 * differs, { orderOnly: true, difference }.
 */
function documentDifference(what, golden, name, value) {
  const entry = golden.record.files[name];
  if (!entry) return { difference: `${what}: the native run wrote no ${name}` };
  if (documentDigest(value) === entry.documentSha256) return null;
  if (entry.orderFreeSha256 && documentDigest(orderFree(value)) === entry.orderFreeSha256) {
    return { orderOnly: true, difference: `${what}: the same content as the native ${name}, but holes or contacts in another order` };
  }
  if (!entry.stored) return { difference: `${what}: differs from the native ${name} (${entry.size} bytes, only its digest is in the corpus)` };
  return { difference: `${what}: differs from the native ${name}: ${firstDifference(canonicalJson(JSON.parse(goldenText(golden, name))), canonicalJson(value))}` };
}

/** The package's message against the CLI's: "MESSAGE in <T> s" on stdout, or "desia: [SOURCE: ]MESSAGE" on stderr. */
function messageDifference(testCase, record, result) {
  if (record.exit === 0) {
    // A message may have several lines ('joints: milled (…)' above 'designed …'): the time ends the last.
    const lines = record.stdout.split('\n').slice(0, result.message.split('\n').length).join('\n');
    return lines === `${result.message} in <T> s` ? null : `message: the CLI printed ${clip(lines)}, the package says ${clip(result.message)}`;
  }
  const line = record.stderr.split('\n')[0];
  return line === `desia: ${result.message}` || line === `desia: ${testCase.input}: ${result.message}`
    ? null : `message: the CLI printed ${clip(line)}, the package says ${clip(result.message)}`;
}

/**
 * The same case through WebAssembly, against the native corpus: { differences, notes }, both
 * lists of lines; differences is empty when it matches (notes: the known differences in order it
 * accepted, see KNOWN_WASM_ORDER_DIFFERENCES).
 */
export function wasmComparison(testCase, core) {
  const notes = [];
  const differences = wasmDifferencesOf(testCase, core, notes);
  return { differences, notes };
}

function wasmDifferencesOf(testCase, core, notes) {
  const golden = readGolden(testCase);
  if (!golden) return [`no golden record in ${path.relative(root, caseDir(testCase))}: run node scripts/golden.mjs generate`];
  const { record } = golden;
  const diffs = corpusProblems(golden);
  if (diffs.length) return diffs;
  const push = (d) => {
    if (!d) return;
    if (typeof d === 'string') diffs.push(d);
    else if (d.orderOnly && KNOWN_WASM_ORDER_DIFFERENCES.has(testCase.id)) notes.push(`known: ${d.difference}`);
    else diffs.push(d.difference);
  };
  const inputBytes = fs.readFileSync(path.join(root, testCase.input));
  const input = inputBytes.toString('utf8');
  const source = testCase.input;
  let result;
  try {
    if (testCase.kind === 'check') result = core.check(input, { source });
    else if (testCase.kind === 'voxelize') result = core.voxelize(new Uint8Array(inputBytes), { ...testCase.wasm, source });
    else {
      const options = { ...testCase.wasm, source };
      if (options.groups) options.groups = JSON.parse(fs.readFileSync(path.join(root, options.groups), 'utf8')).groups;
      const design = { voxel: 'designVoxel', plate: 'designPlate', frame: 'designFrame' }[testCase.kind];
      result = core[design](input, options);
    }
  } catch (error) {
    if (record.exit !== 2) return [`the package threw ${error.name} (${error.code}): ${error.message}; the CLI exited ${record.exit}`];
    const line = record.stderr.split('\n')[0];
    if (line !== `desia: error: ${error.message}`) diffs.push(`error: the CLI printed ${clip(line)}, the package threw ${clip(error.message)}`);
    if (error.code !== 'bad-input') diffs.push(`error code: expected bad-input, got ${error.code}`);
    return diffs;
  }
  if (record.exit === 2) return [`the package returned where the CLI refused the input: ${record.stderr.split('\n')[0]}`];

  if (testCase.kind === 'check') {
    push(documentDifference('check report', golden, 'check.json', result));
    const verdict = result.interlocking ? 0 : 1;
    if (verdict !== record.exit) diffs.push(`check: interlocking ${result.interlocking}, the CLI exited ${record.exit}`);
    return diffs;
  }
  if (testCase.kind === 'voxelize') {
    if (testCase.output.endsWith('.puz')) {
      const puz = core.toPuz(result);
      const d = firstDifference(goldenText(golden, 'result.puz'), puz);
      if (d) diffs.push(`toPuz(voxelize(...)) against the CLI's result.puz: ${d}`);
    } else {
      push(documentDifference('voxelize document', golden, 'result.json', result));
    }
    return diffs;
  }

  // Designs.
  const success = result.status === 'success';
  if (success !== (record.exit === 0)) {
    return [`status ${result.status} (${result.message}); the CLI exited ${record.exit}: ${clip((record.exit === 0 ? record.stdout : record.stderr).split('\n')[0])}`];
  }
  push(messageDifference(testCase, record, result));
  if (success) {
    const resultName = testCase.output;
    if (resultName.endsWith('.puz')) {
      const d = firstDifference(goldenText(golden, resultName), result.puz ?? '');
      if (d) diffs.push(`puz against the CLI's ${resultName}: ${d}`);
    } else {
      push(documentDifference('document', golden, resultName, result.document));
    }
    const stem = resultName.replace(/\.(json|puz)$/, '');
    // The verification is the check the designer ran: plates with both methods, the others DBG.
    const verificationFile = testCase.kind === 'plate' ? `${stem}.check-both.json` : `${stem}.check.json`;
    push(documentDifference('verification', golden, verificationFile, result.verification));
    // And the package's check of the document it returned, as `desia check RESULT --json`.
    const recheck = core.check(resultName.endsWith('.puz') ? result.puz : JSON.stringify(result.document), { source: `$OUT/${resultName}` });
    push(documentDifference('check of the result', golden, `${stem}.check.json`, recheck));
  } else if (result.document !== null || result.puz !== null) {
    diffs.push(`status ${result.status} with a document`);
  }
  if (record.files['repaired.json']) {
    if (!result.repair) diffs.push('the CLI wrote repaired.json, the package gave no repair');
    else push(documentDifference('repair', golden, 'repaired.json', result.repair.document));
  }
  return diffs;
}

// ---------------------------------------------------------------------------------------------
// Generate and compare

function selected(only) {
  return only ? cases.filter((c) => c.id.includes(only)) : cases;
}

async function pool(items, jobs, work) {
  const results = new Array(items.length);
  let next = 0;
  await Promise.all(Array.from({ length: Math.min(jobs, items.length) }, async () => {
    while (next < items.length) {
      const i = next++;
      results[i] = await work(items[i], i);
    }
  }));
  return results;
}

function writeCase(testCase, fresh) {
  const dir = caseDir(testCase);
  fs.rmSync(dir, { recursive: true, force: true });
  fs.mkdirSync(dir, { recursive: true });
  for (const [name, bytes] of fresh.files) if (fresh.record.files[name].stored) fs.writeFileSync(path.join(dir, name), bytes);
  fs.writeFileSync(path.join(dir, 'record.json'), `${JSON.stringify(fresh.record, null, 2)}\n`);
}

function removeStale() {
  const keep = new Set(cases.map((c) => c.id));
  const walk = (dir) => {
    for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
      const full = path.join(dir, entry.name);
      if (!entry.isDirectory()) continue;
      const id = path.relative(casesDir, full);
      if (fs.existsSync(path.join(full, 'record.json'))) {
        if (!keep.has(id)) fs.rmSync(full, { recursive: true, force: true });
      } else {
        walk(full);
        if (fs.readdirSync(full).length === 0) fs.rmdirSync(full);
      }
    }
  };
  if (fs.existsSync(casesDir)) walk(casesDir);
}

function outcome(record) {
  if (record.kind === 'check') return `exit ${record.exit}`;
  const line = (record.exit === 0 ? record.stdout : record.stderr).split('\n')[0];
  return `exit ${record.exit}: ${line.length > 110 ? `${line.slice(0, 110)}…` : line}`;
}

async function generate({ only, jobs }) {
  const chosen = selected(only);
  const started = performance.now();
  const runs = await pool(chosen, jobs, async (testCase) => {
    const fresh = await runNative(testCase);
    writeCase(testCase, fresh);
    return fresh;
  });
  if (!only) removeStale();
  const manifest = {
    about: 'The golden corpus: see tests/golden/README.md. Written by node scripts/golden.mjs generate.',
    cli: (await run(defaultCli, ['--version'], root)).stdout.trim(),
    cases: cases.map((c) => {
      const record = readGolden(c)?.record;
      return { id: c.id, kind: c.kind, wasm: Boolean(c.wasm), command: record?.command, exit: record?.exit };
    }),
  };
  fs.writeFileSync(path.join(goldenDir, 'manifest.json'), `${JSON.stringify(manifest, null, 2)}\n`);
  let slow = 0;
  for (const [i, fresh] of runs.entries()) {
    const flag = fresh.seconds > CASE_BUDGET_SECONDS ? '  <-- over the budget' : '';
    if (flag) slow += 1;
    console.log(`${fresh.seconds.toFixed(2).padStart(6)} s  ${chosen[i].id}  ${outcome(fresh.record)}${flag}`);
  }
  const total = runs.reduce((sum, r) => sum + r.seconds, 0);
  console.log(`generated ${runs.length} cases in ${((performance.now() - started) / 1000).toFixed(1)} s (${total.toFixed(1)} s of runs, ${jobs} at a time)`
    + (slow ? `; ${slow} over ${CASE_BUDGET_SECONDS} s` : ''));
}

async function compare({ only, jobs, native, wasm }) {
  const chosen = selected(only);
  let failed = 0;
  if (native) {
    const started = performance.now();
    await pool(chosen, jobs, async (testCase) => {
      const diffs = nativeDifferences(testCase, await runNative(testCase));
      if (diffs.length) {
        failed += 1;
        console.log(`DIFFERS natively: ${testCase.id}\n${diffs.map((d) => `  ${d}`).join('\n')}`);
      }
    });
    console.log(`native: ${chosen.length} cases compared in ${((performance.now() - started) / 1000).toFixed(1)} s`);
  }
  if (wasm) {
    const started = performance.now();
    const core = await loadWasmCore();
    const wasmCases = chosen.filter((c) => c.wasm);
    for (const testCase of wasmCases) {
      const { differences, notes } = wasmComparison(testCase, core);
      if (differences.length) {
        failed += 1;
        console.log(`DIFFERS in WebAssembly: ${testCase.id}\n${differences.map((d) => `  ${d}`).join('\n')}`);
      }
      for (const note of notes) console.log(`note, WebAssembly: ${testCase.id}: ${note}`);
    }
    console.log(`WebAssembly: ${wasmCases.length} cases compared in ${((performance.now() - started) / 1000).toFixed(1)} s`);
  }
  console.log(failed ? `${failed} case(s) differ from the golden corpus` : 'no differences');
  return failed ? 1 : 0;
}

async function main(argv) {
  const [command, ...rest] = argv;
  const flags = { only: null, jobs: os.availableParallelism?.() ?? os.cpus().length, native: true, wasm: true };
  for (let i = 0; i < rest.length; i += 1) {
    if (rest[i] === '--only') flags.only = rest[++i];
    else if (rest[i] === '--jobs') flags.jobs = Math.max(1, Number(rest[++i]) || 1);
    else if (rest[i] === '--native') flags.wasm = false;
    else if (rest[i] === '--wasm') flags.native = false;
    else throw new Error(`unknown option ${rest[i]}`);
  }
  if (command === 'generate') return generate(flags).then(() => 0);
  if (command === 'compare') return compare(flags);
  if (command === 'list') {
    for (const c of selected(flags.only)) console.log(`${c.id}\t${c.wasm ? 'native+wasm' : 'native'}\tdesia ${c.args.join(' ')}`);
    return 0;
  }
  console.error('usage: node scripts/golden.mjs generate|compare|list [--only TEXT] [--jobs N] [--native|--wasm]');
  return 2;
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main(process.argv.slice(2)).then((code) => { process.exitCode = code; }, (error) => {
    console.error(error.stack ?? String(error));
    process.exitCode = 2;
  });
}
