// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 14 through the package: every hostile input (normals with 1e-17 and 1e-200 residues, a
// document GLPK cycled on, huge normals, documents nested 100,000 levels deep, 800 distinct
// normals, Fig. 4 turned by right angles) gets from `desia.check` in its worker the verdict the
// native CLI gives, or the same bad-input error; never a crashed worker, and the worker keeps
// answering afterwards.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, DesiaError } from '../../wasm/index.js';
import { referenceDir, requireBuilt, root, runCli } from './support.mjs';

requireBuilt(path.join(root, 'dist/desia_wasm.wasm'), 'scripts/build.sh wasm');
const desia = await createDesia();
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-hostile-'));
after(async () => {
  await desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

const figure4 = JSON.parse(fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8'));

function axisRotation(axis, quarterTurns) {
  const t = (quarterTurns * Math.PI) / 2;
  const c = Math.cos(t);
  const s = Math.sin(t);
  return [
    [[1, 0, 0], [0, c, -s], [0, s, c]],
    [[c, 0, s], [0, 1, 0], [-s, 0, c]],
    [[c, -s, 0], [s, c, 0], [0, 0, 1]],
  ][axis];
}

function multiply(a, b) {
  return a.map((row, i) => [0, 1, 2].map((j) => a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j]));
}

function turned(document, rotation) {
  const copy = structuredClone(document);
  for (const contact of copy.contacts) {
    const n = contact.normal;
    contact.normal = rotation.map((row) => row[0] * n[0] + row[1] * n[1] + row[2] * n[2]);
  }
  return copy;
}

/** A ring of 10 parts with `count` contacts of distinct random unit normals (seeded). */
function normalRing(count) {
  let state = 12345;
  const random = () => {
    state = (state * 1103515245 + 12345) % 2147483648;
    return (state / 2147483648) * 2 - 1;
  };
  const contacts = [];
  while (contacts.length < count) {
    const n = [random(), random(), random()];
    const length = Math.hypot(...n);
    if (length > 1 || length < 0.01) continue;
    const a = contacts.length % 10;
    contacts.push({ a: a + 1, b: ((a + 1) % 10) + 1, normal: n.map((x) => x / length) });
  }
  return { kind: 'contacts', parts: Array.from({ length: 10 }, (_, i) => ({ id: i + 1 })), contacts };
}

function nested(section, open, inner, close, depth) {
  const kind = section === 'plates' ? 'plate' : 'frame';
  return `{"kind":"${kind}","parts":[{"id":1}],"contacts":[],"${section}":${open.repeat(depth)}${inner}${close.repeat(depth)}}`;
}

function cases() {
  const list = [];
  for (const name of fs.readdirSync(path.join(root, 'tests/data/contacts')).sort()) {
    list.push([name, fs.readFileSync(path.join(root, 'tests/data/contacts', name), 'utf8')]);
  }
  // Fig. 4 turned by two right angles, computed with cos/sin (1e-17 residues): these gave exit 3
  // and wrong verdicts before.
  for (const [a1, k1, a2, k2] of [[0, 1, 2, 1], [1, 2, 2, 2], [0, 3, 1, 1], [2, 1, 0, 2]]) {
    const rotation = multiply(axisRotation(a2, k2), axisRotation(a1, k1));
    list.push([`figure 4 turned ${a1}${k1}${a2}${k2}`, JSON.stringify(turned(figure4, rotation))]);
  }
  list.push(['800 distinct normals', JSON.stringify(normalRing(800))]);
  list.push(['plates nested 100,000 deep', nested('plates', '[', '', ']', 100000)]);
  list.push(['frame nested 100,000 deep', nested('frame', '{"a":', '1', '}', 100000)]);
  return list;
}

test('the package and the CLI agree on every hostile input, and the worker survives', async () => {
  const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');
  let verdicts = 0;
  let errors = 0;
  for (const [name, text] of cases()) {
    const file = path.join(tmp, 'input.json');
    fs.writeFileSync(file, text);
    for (const method of ['dbg', 'lp', 'both']) {
      const cli = runCli(['check', file, '--method', method, '--json']);
      assert.ok([0, 1, 2].includes(cli.status), `${name} (${method}): CLI exit ${cli.status}: ${cli.stderr}`);
      if (cli.status === 2) {
        const expected = cli.stderr.replace(/^desia: error: /, '').trim().replace(file, 'input.json');
        await assert.rejects(desia.check(text, { method, source: 'input.json' }), (error) => {
          assert.ok(error instanceof DesiaError, String(error));
          assert.equal(error.code, 'bad-input');
          assert.equal(error.fatal, false);
          assert.equal(error.message, expected);
          return true;
        }, `${name} (${method})`);
        errors += 1;
        continue;
      }
      const expected = JSON.parse(cli.stdout);
      const report = await desia.check(text, { method, source: 'input.json' });
      assert.equal(report.verdict, expected.verdict, `${name} (${method}): ${report.reason}`);
      assert.equal(report.key, expected.key, `${name} (${method})`);
      assert.equal(report.baseDirectionCount, expected.baseDirectionCount, `${name} (${method})`);
      verdicts += 1;
    }
  }
  assert.ok(verdicts >= 24 && errors >= 6, `${verdicts} verdicts, ${errors} errors`);
  // Still the same worker, still answering.
  assert.equal((await desia.check(k9)).verdict, 'interlocking');
});

test('Fig. 4 turned stays "not interlocking" under the LP test; 800 normals leave out the graphs', async () => {
  const rotation = multiply(axisRotation(2, 2), axisRotation(1, 2));
  const report = await desia.check(JSON.stringify(turned(figure4, rotation)), { method: 'lp' });
  assert.equal(report.verdict, 'not-interlocking');
  assert.match(report.reason, /can move at once in different directions/);
  const ring = await desia.check(JSON.stringify(normalRing(800)), { method: 'dbg' });
  assert.equal(ring.verdict, 'deadlocked');
  assert.equal(ring.graphsOmitted, true);
  assert.equal(ring.graphs.length, 0);
  assert.ok(ring.baseDirectionCount > 300000, String(ring.baseDirectionCount));
  const small = normalRing(30);
  const all = await desia.check(JSON.stringify(small), { method: 'dbg', graphs: true });
  assert.equal(all.graphs.length, all.baseDirectionCount);
  assert.ok(all.baseDirectionCount > 128);
  await assert.rejects(desia.check(JSON.stringify(small), { graphs: 'yes' }), /check: graphs must be a boolean, got a string/);
});
