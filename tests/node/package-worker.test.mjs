// SPDX-License-Identifier: GPL-3.0-or-later
// The worker behind createDesia in node: an AbortSignal stops a long design within a moment and
// the next call runs in a fresh worker, sessions in a stopped worker are lost, a crashed worker
// fails its call and is replaced, terminate() fails what is pending, an idle worker lets the
// process exit, and { worker: false } keeps the same API in-process.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';
import { pathToFileURL } from 'node:url';

import { createDesia, DesiaError } from '../../wasm/index.js';
import { referenceDir, root } from './support.mjs';

const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');
const cubeShape = fs.readFileSync(path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz'), 'utf8');
const bunnyShape = fs.readFileSync(path.join(referenceDir, 'input_puz/bunny_origin.puz'), 'utf8');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-worker-'));
const indexUrl = pathToFileURL(path.join(root, 'wasm/index.js')).href;
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

/** A design of the 80-part bunny: 20 s or more in WebAssembly, far longer than any abort takes. */
const longDesign = { parts: 80, seed: 3, timeLimit: 300 };

function isAbortError(error) {
  return error instanceof DOMException && error.name === 'AbortError';
}

/** Resolves once `onProgress` has been called `count` times (the design is surely running). */
function progressCounter(count) {
  let calls = 0;
  let reached;
  const promise = new Promise((resolve) => { reached = resolve; });
  return { onProgress: () => { if (++calls === count) reached(); }, running: promise, calls: () => calls };
}

test('aborting a running design stops it within a second; the next call runs in a fresh worker', async () => {
  const desia = await createDesia();
  try {
    const controller = new AbortController();
    const progress = progressCounter(3);
    const design = desia.designVoxel(bunnyShape, { ...longDesign, onProgress: progress.onProgress, signal: controller.signal });
    await progress.running;
    const abortedAt = performance.now();
    controller.abort();
    await assert.rejects(design, (error) => isAbortError(error));
    assert.ok(performance.now() - abortedAt < 1000, `took ${performance.now() - abortedAt} ms`);
    const callsAfterAbort = progress.calls();
    // The next calls work, in a new worker; the old one sends nothing any more.
    assert.equal((await desia.check(k9)).key, 1);
    const small = await desia.designVoxel(cubeShape, { parts: 7, seed: 3 });
    assert.equal(small.status, 'success');
    assert.equal(progress.calls(), callsAfterAbort);
    // A reason given to abort() is what the call rejects with.
    const withReason = new AbortController();
    const second = desia.designVoxel(bunnyShape, { ...longDesign, signal: withReason.signal });
    setTimeout(() => withReason.abort(new Error('user pressed stop')), 200);
    await assert.rejects(second, /^Error: user pressed stop$/);
  } finally {
    await desia.terminate();
  }
});

test('an already aborted signal rejects at once; aborting a queued call leaves the running one alone', async () => {
  const desia = await createDesia();
  try {
    await assert.rejects(desia.check(k9, { signal: AbortSignal.abort() }), (error) => isAbortError(error));
    const reason = new Error('not needed');
    await assert.rejects(desia.designVoxel(cubeShape, { parts: 5, signal: AbortSignal.abort(reason) }), (error) => error === reason);

    const running = new AbortController();
    const progress = progressCounter(1);
    const design = desia.designVoxel(bunnyShape, { parts: 20, seed: 2, onProgress: progress.onProgress, signal: running.signal });
    const queued = new AbortController();
    const check = desia.check(k9, { signal: queued.signal });
    await progress.running;
    queued.abort();
    await assert.rejects(check, (error) => isAbortError(error));
    const result = await design;
    assert.equal(result.status, 'success', result.message);
    assert.equal(result.document.parts.length, 20);
    // Aborting after the call finished changes nothing.
    running.abort();
    assert.equal((await desia.check(k9)).key, 1);
  } finally {
    await desia.terminate();
  }
});

test('sessions in a stopped worker are lost; a new session works', async () => {
  const desia = await createDesia();
  try {
    const session = await desia.designSession(cubeShape, { parts: 6, seed: 1 });
    assert.equal(await session.next(), true);
    const controller = new AbortController();
    const progress = progressCounter(1);
    const design = desia.designVoxel(bunnyShape, { ...longDesign, onProgress: progress.onProgress, signal: controller.signal });
    await progress.running;
    controller.abort();
    await assert.rejects(design, (error) => isAbortError(error));
    for (const call of [() => session.next(), () => session.state(), () => session.childCount()]) {
      await assert.rejects(call(), (error) => {
        assert.ok(error instanceof DesiaError);
        assert.equal(error.code, 'session-lost');
        assert.match(error.message, /^designSession: the session was lost/);
        return true;
      });
    }
    await session.dispose(); // nothing left to free: resolves
    const fresh = await desia.designSession(cubeShape, { parts: 6, seed: 1 });
    assert.equal(await fresh.next(), true);
    assert.equal((await fresh.state()).partsPlaced, 2);
    await fresh.dispose();
  } finally {
    await desia.terminate();
  }
});

test('a crashed worker fails its call with a fatal DesiaError and is replaced by the next call', async () => {
  // A stand-in worker script: the package worker, with its message listener wrapped so that it
  // dies on two magic inputs.
  const crashingWorker = path.join(tmp, 'crashing-worker.mjs');
  fs.writeFileSync(crashingWorker, `
import { parentPort } from 'node:worker_threads';
const on = parentPort.on.bind(parentPort);
parentPort.on = (type, listener) => on(type, type !== 'message' ? listener : (message) => {
  if (message?.type === 'run' && message.args?.[0] === 'CRASH') throw new WebAssembly.RuntimeError('unreachable');
  if (message?.type === 'run' && message.args?.[0] === 'EXIT') process.exit(7);
  // What the host posts when the core traps inside a call (the module is then unusable).
  if (message?.type === 'run' && message.args?.[0] === 'TRAP') {
    parentPort.postMessage({ type: 'error', id: message.id, message: 'WebAssembly trap: unreachable', code: 'internal', fatal: true });
    return;
  }
  listener(message);
});
await import(${JSON.stringify(pathToFileURL(path.join(root, 'wasm/worker.js')).href)});
`);
  const desia = await createDesia({ workerUrl: pathToFileURL(crashingWorker) });
  try {
    const session = await desia.designSession(cubeShape, { parts: 5 });
    await assert.rejects(desia.check('CRASH'), (error) => {
      assert.ok(error instanceof DesiaError, String(error));
      assert.equal(error.code, 'internal');
      assert.equal(error.fatal, true);
      assert.match(error.message, /^the desia worker stopped: it crashed: unreachable; the next call starts a new one$/);
      return true;
    });
    await assert.rejects(session.next(), (error) => error.code === 'session-lost');
    assert.equal((await desia.check(k9)).key, 1);
    // Calls queued behind the one that kills the worker run in the next worker.
    const exit = desia.check('EXIT');
    const queued = desia.check(k9);
    await assert.rejects(exit, /the desia worker stopped: it exited with code 7/);
    assert.equal((await queued).key, 1);
    // A trap reported by the host: the call fails, the worker (and its sessions) is replaced.
    const second = await desia.designSession(cubeShape, { parts: 5 });
    await assert.rejects(desia.check('TRAP'), (error) => error instanceof DesiaError && error.fatal === true
      && error.code === 'internal' && error.message === 'WebAssembly trap: unreachable');
    await assert.rejects(second.state(), (error) => error.code === 'session-lost');
    assert.equal((await desia.check(k9)).key, 1);
  } finally {
    await desia.terminate();
  }
});

test('terminate() fails pending calls with code "terminated"; later calls start a fresh worker', async () => {
  const desia = await createDesia();
  const progress = progressCounter(1);
  const design = desia.designVoxel(bunnyShape, { ...longDesign, onProgress: progress.onProgress });
  const queued = desia.check(k9);
  const outcomes = Promise.allSettled([design, queued]);
  await progress.running;
  await desia.terminate();
  for (const outcome of await outcomes) {
    assert.equal(outcome.status, 'rejected');
    assert.ok(outcome.reason instanceof DesiaError, String(outcome.reason));
    assert.equal(outcome.reason.code, 'terminated');
    assert.match(outcome.reason.message, /^desia was terminated \(terminate\(\) was called\) before this call finished$/);
  }
  assert.equal((await desia.check(k9)).key, 1);
  await desia.terminate();
});

test('an idle worker does not keep node running, a busy one does', async () => {
  // No terminate(), and nothing awaited at the top level after the call is made: the process
  // must stay alive for the answers (the worker is ref'd while busy) and then exit by itself.
  const script = path.join(tmp, 'idle.mjs');
  fs.writeFileSync(script, `
import { createDesia } from ${JSON.stringify(indexUrl)};
const desia = await createDesia();
const session = await desia.designSession(${JSON.stringify(cubeShape)}, { parts: 5 });
desia.check(${JSON.stringify(k9)}).then((report) => console.log('verdict', report.verdict));
desia.designVoxel(${JSON.stringify(cubeShape)}, { parts: 7, seed: 3 }).then((result) => console.log('design', result.status));
`);
  const started = performance.now();
  const child = spawn(process.execPath, [script], { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  child.stdout.on('data', (chunk) => { stdout += chunk; });
  child.stderr.on('data', (chunk) => { stderr += chunk; });
  const killer = setTimeout(() => child.kill('SIGKILL'), 15_000);
  const [code, signal] = await new Promise((resolve) => child.once('exit', (...args) => resolve(args)));
  clearTimeout(killer);
  assert.equal(signal, null, `the child did not exit by itself within 15 s; stdout: ${stdout}; stderr: ${stderr}`);
  assert.equal(code, 0, stderr);
  assert.equal(stdout, 'verdict interlocking\ndesign success\n');
  assert.ok(performance.now() - started < 10_000, `took ${performance.now() - started} ms`);
});

test('in-process ({ worker: false }): same answers; an abort works before a call starts or from onProgress', async () => {
  const desia = await createDesia({ worker: false });
  try {
    assert.equal((await desia.check(k9)).key, 1);
    await assert.rejects(desia.check(k9, { signal: AbortSignal.abort() }), (error) => isAbortError(error));
    // Aborted while queued behind another call (the thread was free in between).
    const controller = new AbortController();
    const first = desia.check(k9);
    const second = desia.check(k9, { signal: controller.signal });
    const secondRejected = assert.rejects(second, (error) => isAbortError(error));
    controller.abort();
    assert.equal((await first).key, 1);
    await secondRejected;
    // Aborted from inside onProgress: the search stops at its next node.
    const fromProgress = new AbortController();
    let calls = 0;
    const design = desia.designVoxel(bunnyShape, {
      ...longDesign,
      signal: fromProgress.signal,
      onProgress: () => { if (++calls === 3) fromProgress.abort(); },
    });
    const started = performance.now();
    await assert.rejects(design, (error) => isAbortError(error));
    assert.ok(performance.now() - started < 5000);
    assert.equal(calls, 3);
    const session = await desia.designSession(cubeShape, { parts: 5 });
    assert.equal(await session.next(), true);
    await desia.terminate();
    await assert.rejects(session.next(), (error) => error.code === 'session-lost');
    await assert.rejects(desia.check('4 4 4\n1 1 1 1\n1 1\n', { source: 'ragged.puz' }),
      (error) => error instanceof DesiaError && error.code === 'bad-input'
        && error.message === 'ragged.puz:3: row 2 of layer 1 has 2 values, expected Nx = 4');
  } finally {
    await desia.terminate();
  }
});
