// SPDX-License-Identifier: GPL-3.0-or-later
// The package's argument checks, in the synchronous core and the promise API alike: options that
// are not a plain object or carry an unknown name, values JSON cannot carry and session child
// indices that are not indices are DesiaErrors with code 'bad-input' naming the function and the
// value (never a silent default); codes stay within the documented set; loading from given bytes
// (wasmBinary) works in a fresh node process; a worker that never loads the core is given up.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';
import { pathToFileURL } from 'node:url';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { describeError } from '../../wasm/host.js';
import { referenceDir, requireBuilt, root } from './support.mjs';

requireBuilt(path.join(root, 'dist/desia_wasm.wasm'), 'scripts/build.sh wasm');
const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');
const cubeShape = fs.readFileSync(path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz'), 'utf8');
const octahedron = 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n'
  + 'f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-input-'));
const indexUrl = pathToFileURL(path.join(root, 'wasm/index.js')).href;
const wasmFile = path.join(root, 'dist/desia_wasm.wasm');

const core = await loadDesiaModule();
const desia = await createDesia();
after(async () => {
  await desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

/** A predicate for assert.throws / rejects: a DesiaError with `code`, not fatal, matching `message`. */
function desiaError(code, message) {
  return (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, code);
    assert.equal(error.fatal, false);
    assert.match(error.message, message);
    return true;
  };
}

test('options that are not a plain object are refused, naming the function and the type', async () => {
  const cases = [
    ['exportAssembly', [k9, 'obj'], /^exportAssembly: options must be an object, got a string \("obj"\)$/],
    ['designVoxel', [cubeShape, 'abc'], /^designVoxel: options must be an object, got a string \("abc"\)$/],
    ['check', [k9, null], /^check: options must be an object, got null$/],
    ['check', [k9, ['lp']], /^check: options must be an object, got an array$/],
    ['parseDocument', [k9, 7], /^parseDocument: options must be an object, got a number \(7\)$/],
    ['voxelize', [octahedron, new Map()], /^voxelize: options must be an object, got a Map$/],
    ['toPuz', [k9, true], /^toPuz: options must be an object, got a boolean \(true\)$/],
    ['designSession', [cubeShape, 'parts=5'], /^designSession: options must be an object, got a string/],
  ];
  for (const [name, args, message] of cases) {
    assert.throws(() => core[name](...args), desiaError('bad-input', message), `core.${name}`);
    await assert.rejects(desia[name](...args), desiaError('bad-input', message), `desia.${name}`);
  }
  // Without options (or with undefined) the defaults apply.
  assert.equal(core.check(k9, undefined).key, 1);
  assert.equal((await desia.check(k9)).key, 1);
});

test('unknown option names are refused with the accepted ones listed', async () => {
  const cases = [
    ['exportAssembly', [k9, { fromat: 'obj' }], 'fromat', 'format, part, voxelSize, clearance, source, sheet, sheetIndex, kerf, spacing or hairline'],
    ['check', [k9, { methd: 'lp' }], 'methd', 'method, source or graphs'],
    ['parseDocument', [k9, { name: 'k9' }], 'name', 'source'],
    ['voxelize', [octahedron, { resolutoin: 8 }], 'resolutoin', 'resolution or source'],
    ['toPuz', [k9, { sauce: 'k9.puz' }], 'sauce', 'source'],
  ];
  const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  for (const [name, args, key, accepted] of cases) {
    assert.throws(() => core[name](...args),
      desiaError('bad-input', new RegExp(`^${name}: unknown option '${key}' \\(expected ${escape(accepted)}\\)$`)), `core.${name}`);
    // The promise API accepts `signal` too, and says so.
    await assert.rejects(desia[name](...args),
      desiaError('bad-input', new RegExp(`^${name}: unknown option '${key}' \\(expected .*${accepted.split(/,? /)[0]}.* or signal\\)$`)), `desia.${name}`);
  }
});

test('option values JSON cannot carry are bad input, not an internal error', async () => {
  assert.throws(() => core.designVoxel(cubeShape, { parts: 5n }),
    desiaError('bad-input', /^designVoxel: option 'parts' must be JSON data .*got a bigint \(5n\)$/));
  assert.throws(() => core.designSession(cubeShape, { parts: 5, seed: 1n }), desiaError('bad-input', /option 'seed' .*bigint/));
  // A BigInt survives the trip to the worker; the core's facade there refuses it.
  await assert.rejects(desia.designVoxel(cubeShape, { parts: 5n }), desiaError('bad-input', /option 'parts' .*bigint/));
  assert.throws(() => core.exportAssembly(k9, { part: 1n }), desiaError('bad-input', /^exportAssembly: part must be an integer \(32-bit\), got a bigint/));
  assert.throws(() => core.check(k9, { source: 1n }), desiaError('bad-input', /^check: source must be a string, got a bigint/));
  // A function among the design options is not silently dropped either.
  assert.throws(() => core.designVoxel(cubeShape, { parts: 5, seed: () => 1 }), desiaError('bad-input', /option 'seed' .*got a function/));
  // Ranges are named by the core, types by JavaScript.
  assert.throws(() => core.voxelize(octahedron, { resolution: 2 ** 40 }), desiaError('bad-input', /^voxelize: resolution must be an integer \(32-bit\)/));
  assert.throws(() => core.voxelize(octahedron, { resolution: 0 }), desiaError('bad-input', /resolution 0 is out of range \(1 to 1024/));
  assert.equal((await desia.check(k9)).key, 1, 'the worker is still fine');
});

test('a session child index must be an integer from 0 to 2^31 - 1', async () => {
  const local = core.designSession(cubeShape, { parts: 6, seed: 2 });
  const remote = await desia.designSession(cubeShape, { parts: 6, seed: 2 });
  try {
    assert.equal(local.next(), true);
    assert.equal(await remote.next(), true);
    for (const bad of ['x', 2.7, null, true, undefined, -1, 2 ** 31, 1e12, NaN]) {
      for (const method of ['choose', 'preview']) {
        const message = new RegExp(`^designSession: ${method}: the child index must be an integer from 0 to 2147483647, got `);
        assert.throws(() => local[method](bad), desiaError('bad-input', message), `local ${method}(${String(bad)})`);
        await assert.rejects(remote[method](bad), desiaError('bad-input', message), `remote ${method}(${String(bad)})`);
      }
    }
    // Nothing moved.
    assert.equal(local.state().partsPlaced, 2);
    assert.equal((await remote.state()).partsPlaced, 2);
    // A valid index that is not a child is the core's error.
    assert.throws(() => local.preview(2 ** 31 - 1), desiaError('bad-input', /child 2147483647 does not exist/));
    await assert.rejects(remote.preview(2 ** 31 - 1), desiaError('bad-input', /child 2147483647 does not exist/));
  } finally {
    local.dispose();
    await remote.dispose();
  }
});

test('error codes stay within the documented set; internal errors are fatal', async () => {
  assert.equal(new DesiaError('x', 'ENOENT').code, 'internal');
  assert.equal(new DesiaError('x', 'too-large').code, 'too-large');
  assert.deepEqual(describeError(Object.assign(new Error('gone'), { code: 'ENOENT' })), { message: 'gone', code: 'internal', fatal: true });
  assert.deepEqual(describeError(Object.assign(new Error('bad'), { code: 'bad-input' })), { message: 'bad', code: 'bad-input', fatal: false });
  assert.equal(describeError(new WebAssembly.RuntimeError('unreachable')).fatal, true);
  assert.equal(describeError(new Error('Aborted(OOM)')).fatal, true);

  const missing = path.join(tmp, 'no-such.wasm');
  const loadFailure = (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, 'internal');
    assert.match(error.message, /^could not load the desia WebAssembly module: .*ENOENT/);
    return true;
  };
  await assert.rejects(loadDesiaModule({ wasmUrl: missing }), loadFailure);
  await assert.rejects(loadDesiaModule({ wasmUrl: pathToFileURL(missing) }), loadFailure);
  await assert.rejects(createDesia({ wasmUrl: missing }), loadFailure);
  await assert.rejects(createDesia({ wasmUrl: missing, worker: false }), loadFailure);
});

test('wasmBinary loads in a fresh node process: the synchronous core, a worker and in-process', () => {
  // Each in its own process: a load without wasmBinary in the same process would define the
  // globals Emscripten's output needs in node and hide a missing definition.
  const scripts = {
    core: 'const core = await loadDesiaModule({ wasmBinary: bytes }); console.log(core.check(k9).key);',
    worker: 'const desia = await createDesia({ wasmBinary: bytes }); console.log((await desia.check(k9)).key); await desia.terminate();',
    'in-process': 'const desia = await createDesia({ wasmBinary: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), worker: false });'
      + ' console.log((await desia.check(k9)).key); await desia.terminate();',
  };
  for (const [name, body] of Object.entries(scripts)) {
    const script = `import fs from 'node:fs';
import { createDesia, loadDesiaModule } from ${JSON.stringify(indexUrl)};
const bytes = fs.readFileSync(${JSON.stringify(wasmFile)});
const k9 = fs.readFileSync(${JSON.stringify(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'))}, 'utf8');
${body}`;
    // Run from a folder without the package, so nothing resolves by accident relative to it.
    const result = spawnSync(process.execPath, ['--input-type=module', '-e', script], { cwd: tmp, encoding: 'utf8', timeout: 120_000 });
    assert.equal(result.status, 0, `${name}: ${result.stderr}`);
    assert.equal(result.stdout.trim(), '1', `${name}: the key of K9 is part 1`);
  }
});

test('a worker that never loads the core is given up after startTimeout', async () => {
  const silentWorker = path.join(tmp, 'silent-worker.mjs');
  fs.writeFileSync(silentWorker, "import { parentPort } from 'node:worker_threads';\nparentPort.on('message', () => {});\n");
  const started = performance.now();
  await assert.rejects(createDesia({ workerUrl: pathToFileURL(silentWorker), startTimeout: 300 }), (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, 'internal');
    assert.equal(error.fatal, true);
    assert.match(error.message, /^the desia worker did not load the core within 0\.3 s/);
    return true;
  });
  assert.ok(performance.now() - started < 10_000);
  await assert.rejects(createDesia({ startTimeout: 0 }), desiaError('bad-input', /^createDesia: startTimeout must be a positive number/));
});
