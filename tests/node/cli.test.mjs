// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI's contract: exit 0 interlocking, 1 negative verdict, 2 bad input or usage; clear
// messages naming file and line; never a crash.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { referenceDir, root as projectRoot, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-cli-'));
function writeTemp(name, content) {
  const file = path.join(tmp, name);
  fs.writeFileSync(file, content);
  return file;
}

test('text report of an interlocking puzzle, exit 0', () => {
  const result = runCli(['check', path.join(referenceDir, 'result_puz/Cube_4x4x4_K9_01.puz')]);
  assert.equal(result.status, 0);
  assert.match(result.stdout, /^verdict: interlocking \(method dbg\)$/m);
  assert.match(result.stdout, /^key: part 1, free along \+y$/m);
  assert.match(result.stdout, /^ {2}part 2: \+z 1, \+y 2$/m);
});

test('a puzzle of level 98 (BurrTools\' PelikanBurr): the level, every move, and the JSON steps', () => {
  const file = path.join(projectRoot, 'tests/data/burrtools/PelikanBurr-p0-s0.puz');
  const text = runCli(['check', file]);
  assert.match(text.stdout, /^disassembly: level 98\.2\.5, 108 moves$/m);
  assert.match(text.stdout, /^ {2}move 1: parts? [\d, ]+ {2}[+-][xyz] \d+$/m);
  assert.match(text.stdout, /^ {2}move 108: parts? [\d, ]+ {2}[+-][xyz] out$/m);
  const report = JSON.parse(runCli(['check', file, '--json']).stdout);
  const { disassembly } = report;
  assert.deepEqual(disassembly.level, [98, 2, 5]);
  assert.equal(disassembly.levelMinimal, true);
  assert.equal(disassembly.paths, null);  // no single-part plan: the steps are the plan
  assert.equal(disassembly.steps.length, disassembly.moves);
  assert.equal(disassembly.order.length, 7);
  for (const step of disassembly.steps) {
    assert.equal(step.move.filter((d) => d !== 0).length, 1);
    if (step.out) assert.equal(Math.abs(step.move.find((d) => d !== 0)), 1);
  }
  assert.equal(disassembly.steps.filter((step) => step.out).length, 6);  // 7 parts: 6 separations
  // A six-piece burr whose first move takes three parts out together.
  const burr = JSON.parse(runCli(['check', path.join(projectRoot, 'tests/data/burrtools/SolidSixPieceBurrs-p0-s0.puz'), '--json']).stdout);
  assert.deepEqual(burr.disassembly.steps[0], { parts: [1, 3, 5], move: [1, 0, 0], out: true });
});

test('the .puz layout of later research: comments, voxel sizes, a flat list', () => {
  const file = writeTemp('research.puz', '# a 3-part puzzle\n3 1 1\n0.250000 0.250000 0.250000\n1 2 3\n');
  const result = runCli(['check', file]);
  assert.match(result.stdout, /^parts: 3 \(voxel grid 3x1x1\)$/m);
  const obj = path.join(tmp, 'research.obj');
  assert.equal(runCli(['export', file, '--format', 'obj', '--output', obj]).status, 0);
  const xs = fs.readFileSync(obj, 'utf8').split('\n').filter((l) => l.startsWith('v ')).map((l) => Number(l.split(' ')[1]));
  assert.equal(Math.max(...xs), 0.75);  // three voxels of 0.25
  const bad = runCli(['check', writeTemp('bad-size.puz', '3 1 1\n0.25 zero 0.25\n1 2 3\n')]);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /bad-size\.puz:2:6: the voxel size along y must be a positive number, found 'zero'/);
});

test('an input shape (one part) is a verdict: exit 1 with the reason', () => {
  const result = runCli(['check', path.join(referenceDir, 'input_puz/bunny_origin.puz'), '--json']);
  assert.equal(result.status, 1);
  const report = JSON.parse(result.stdout);
  assert.equal(report.interlocking, false);
  assert.equal(report.parts, 1);
  assert.match(report.reason, /at least three parts/);
});

test('a deadlocked assembly: exit 1, deadlocked, no disassembly but the stuck parts', () => {
  // Cube_4x4x4_K9_01 with a cap of part 2 over the key's column (grid grows to 4x5x4): the key
  // can no longer slide up and nothing else can move.
  const values = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9_01.puz'), 'utf8').trim().split(/\s+/).map(Number);
  const [nx, ny, nz] = values.slice(0, 3);
  const at = (x, y, z) => values[3 + x + nx * (y + ny * z)];
  assert.equal(at(2, 3, 1), 1);
  assert.equal(at(1, 3, 1), 2);
  let text = `${nx} ${ny + 1} ${nz}\n`;
  for (let z = 0; z < nz; z++) {
    for (let y = 0; y <= ny; y++) {
      let row = '';
      for (let x = 0; x < nx; x++) row += `${y < ny ? at(x, y, z) : (z === 1 && (x === 1 || x === 2) ? 2 : 0)} `;
      text += `${row}\n`;
    }
    text += '\n';
  }
  const result = runCli(['check', writeTemp('capped.puz', text), '--json', '--method', 'both']);
  assert.equal(result.status, 1);
  const report = JSON.parse(result.stdout);
  assert.equal(report.verdict, 'deadlocked');
  assert.equal(report.deadlocked, true);
  assert.equal(report.key, null);
  assert.equal(report.disassembly, null);
  // Proven stuck: the search over moves of several parts ran out of positions without a separation.
  assert.deepEqual(report.disassemblyFailure, {
    removed: [], stuck: [1, 2, 3, 4, 5, 6, 7], searchLimitReached: false,
    unseparated: [[1, 2, 3, 4, 5, 6, 7]], level: [], steps: [],
  });
});

const badInputs = [
  ['missing file', null, /cannot open the file/],
  ['wrong header', '4 4\n', /wrong-header\.puz:1: the header must be three integers/],
  ['ragged row', '3 1 1\n1 1\n', /ragged-row\.puz:2: row 1 of layer 1 has 2 values, expected Nx = 3/],
  ['non-integer', '2 1 1\n1 q\n', /non-integer\.puz:2:3: voxel value 'q' is not an integer/],
  ['data after grid', '1 1 1\n1\n\n5 5\n', /data-after-grid\.puz:4:1: unexpected data after the last layer/],
  ['disconnected part', '3 1 1\n1 2 1\n', /part 1 is not face-connected/],
  ['absurd size', '999999999 1 1\n', /grid size Nx 999999999 is out of range/],
  ['binary garbage', Buffer.from([0x7f, 0x45, 0x4c, 0x46, 0x02, 0x01, 0x00]), /not a text file: unexpected byte 0x7f at offset 0/],
  ['malformed json', '{"kind": "voxel", }', /malformed-json\.puz:1:\d+: malformed JSON/],
];

for (const [name, content, message] of badInputs) {
  test(`bad input (${name}): exit 2 and a clear message`, () => {
    const file = content === null ? path.join(tmp, 'does-not-exist.puz') : writeTemp(`${name.replace(/ /g, '-')}.puz`, content);
    const result = runCli(['check', file]);
    assert.equal(result.status, 2, result.stderr);
    assert.equal(result.stdout, '');
    assert.match(result.stderr, message);
    assert.match(result.stderr, /^desia: error: /);
  });
}

test('usage errors: exit 2 with the usage text', () => {
  for (const args of [[], ['frobnicate'], ['check'], ['check', 'a.puz', '--method'], ['check', 'a.puz', '--bogus']]) {
    const result = runCli(args);
    assert.equal(result.status, 2, args.join(' '));
    assert.match(result.stderr, /usage: desia check FILE/);
  }
  const unknownMethod = runCli(['check', path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), '--method', 'simplex']);
  assert.equal(unknownMethod.status, 2);
  assert.match(unknownMethod.stderr, /unknown method 'simplex'/);
});

test('design plate: a verified joint plan (exit 0) that check re-verifies; a cut point is exit 1; bad input exit 2', () => {
  const examples = path.join(referenceDir, '../../../../examples/plate');
  const plan = path.join(tmp, 'table-plan.json');
  const designed = runCli(['design', 'plate', '--input', path.join(examples, 'table.json'), '--output', plan, '--seed', '3']);
  assert.equal(designed.status, 0, designed.stderr);
  assert.match(designed.stdout, /^verdict: interlocking \(method both\)$/m);
  const document = JSON.parse(fs.readFileSync(plan, 'utf8'));
  assert.equal(document.kind, 'plate');
  assert.equal(document.parts.length, 6);
  assert.equal(document.joints.length, 10);
  assert.deepEqual(document.removal.map((step) => step.part), [1, 2, 3, 4, 5, 6]);
  for (const method of ['dbg', 'lp']) {
    const checked = runCli(['check', plan, '--method', method, '--json']);
    assert.equal(checked.status, 0, checked.stdout);
    assert.equal(JSON.parse(checked.stdout).key, 1);
  }
  const again = path.join(tmp, 'table-plan-again.json');
  assert.equal(runCli(['design', 'plate', '--input', path.join(examples, 'table.json'), '--output', again, '--seed', '3']).status, 0);
  assert.equal(fs.readFileSync(again, 'utf8'), fs.readFileSync(plan, 'utf8'), 'same seed, same bytes');

  const chair = runCli(['design', 'plate', '--input', path.join(examples, 'chair_cut_point.json'), '--output', path.join(tmp, 'chair.json')]);
  assert.equal(chair.status, 1);
  assert.match(chair.stderr, /chair_cut_point\.json: plate 5 is a cut point of the parts-graph/);
  assert.equal(fs.existsSync(path.join(tmp, 'chair.json')), false);
  assert.match(chair.stderr, /a repair exists \(added plate 9, a bar joining plates 1 and 6 past cut point 5\): write it with --repair/);
  const repairFile = path.join(tmp, 'chair-repaired.json');
  const repaired = runCli(['design', 'plate', '--input', path.join(examples, 'chair_cut_point.json'), '--output', path.join(tmp, 'chair.json'), '--repair', repairFile]);
  assert.equal(repaired.status, 1, 'the chair as given still cannot interlock');
  assert.match(repaired.stderr, /wrote .*chair-repaired\.json \(design it with desia design plate\)/);
  const proposal = JSON.parse(fs.readFileSync(repairFile, 'utf8'));
  assert.equal(proposal.plates.length, 9);
  const again_ = runCli(['design', 'plate', '--input', repairFile, '--output', path.join(tmp, 'chair-plan.json'), '--joints', 'planned']);
  assert.equal(again_.status, 0, again_.stderr);

  const flat = writeTemp('flat.json', '{"kind":"plate","plates":[{"id":1,"outline":[[0,0,0],[1,0,0],[0,1,0]],"thickness":0}]}');
  const bad = runCli(['design', 'plate', '--input', flat, '--output', path.join(tmp, 'flat-plan.json')]);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /flat\.json: plates\[0\] \(plate 1\)\.thickness: must be positive, found 0/);
  assert.equal(document.jointGeometry, 'cut', 'the joints are cut into the plates by default');
  assert.equal(runCli(['design', 'plate', '--input', path.join(examples, 'table.json'), '--output', path.join(tmp, 'x.json'), '--clearance', 'wide']).status, 2);
  const cutOnly = runCli(['design', 'plate', '--input', path.join(examples, 'mitred_box.json'), '--output', path.join(tmp, 'box.json'), '--joints', 'cut']);
  assert.equal(cutOnly.status, 1, 'mitred edges get no cut joints yet');
  assert.match(cutOnly.stderr, /joints 'planned' gives the paper's graph design alone/);
  // The default, auto: no laser-cut plan, so milled joints, and the output says which and why.
  const box = runCli(['design', 'plate', '--input', path.join(examples, 'mitred_box.json'), '--output', path.join(tmp, 'box.json')]);
  assert.equal(box.status, 0, box.stderr);
  assert.match(box.stdout, /^joints: milled \(no laser-cut plan: no interlocking joint plan exists/m);
  assert.equal(JSON.parse(fs.readFileSync(path.join(tmp, 'box.json'), 'utf8')).jointGeometry, 'milled');
  const planned = runCli(['design', 'plate', '--input', path.join(examples, 'mitred_box.json'), '--output', path.join(tmp, 'box.json'), '--joints', 'planned']);
  assert.equal(planned.status, 0, planned.stderr);
  assert.equal(JSON.parse(fs.readFileSync(path.join(tmp, 'box.json'), 'utf8')).jointGeometry, 'planned');
  // A made-joint search stopped at its limits proves nothing, and auto goes on to the paper's plan:
  // with a node limit (the same on every machine) the icosahedron's milled search (1,139
  // nodes) stops, and the plan (19 nodes) comes.
  const limited = runCli(['design', 'plate', '--input', path.join(examples, 'icosahedron.json'), '--output', path.join(tmp, 'ico.json'), '--node-limit', '100']);
  assert.equal(limited.status, 0, limited.stderr);
  assert.match(limited.stdout, /^joints: planned, nothing is cut: .*no milled plan found within the limits: no plan within the limits \(100 nodes/m);
  assert.equal(JSON.parse(fs.readFileSync(path.join(tmp, 'ico.json'), 'utf8')).jointGeometry, 'planned');
  // One time limit covers auto's attempts, and a search stopped by the clock may not eat all of it:
  // the milled search gets 3/4 of what the cut attempt leaves of 1 s, so the plan still gets its
  // turn. (The milled search needs 6 to 15 s here: a machine more than 8 times faster would find
  // the milled plan within its share, and the first assertion would say so.)
  const hurried = runCli(['design', 'plate', '--input', path.join(examples, 'icosahedron.json'), '--output', path.join(tmp, 'ico.json'), '--time-limit', '1']);
  assert.equal(hurried.status, 0, hurried.stderr);
  assert.match(hurried.stdout, /^joints: planned, nothing is cut: .*no milled plan found within the limits: no plan within the limits/m);
  assert.equal(JSON.parse(fs.readFileSync(path.join(tmp, 'ico.json'), 'utf8')).jointGeometry, 'planned');
});

test('export a designed plate structure as SVG and DXF cut sheets; a sheet too small is named', () => {
  const examples = path.join(referenceDir, '../../../../examples/plate');
  const result = path.join(tmp, 'table-cut.json');
  assert.equal(runCli(['design', 'plate', '--input', path.join(examples, 'table.json'), '--output', result, '--clearance', '0.2']).status, 0);
  const svg = path.join(tmp, 'table.svg');
  const one = runCli(['export', result, '--format', 'svg', '--kerf', '0.1', '--output', svg]);
  assert.equal(one.status, 0, one.stderr);
  assert.match(one.stdout, /6 plates on 1 sheet as svg/);
  const text = fs.readFileSync(svg, 'utf8');
  assert.match(text, /<svg xmlns="http:\/\/www\.w3\.org\/2000\/svg" width="[0-9.]+mm" height="[0-9.]+mm" viewBox="0 0 /);
  assert.equal((text.match(/<g id="plate-/g) || []).length, 6);
  const several = runCli(['export', result, '--format', 'svg', '--sheet', '1200x800', '--output', path.join(tmp, 'sheets.svg')]);
  assert.equal(several.status, 0, several.stderr);
  const count = Number(several.stdout.match(/on (\d+) sheets/)[1]);
  assert.ok(count > 1);
  for (let k = 1; k <= count; k += 1) assert.ok(fs.existsSync(path.join(tmp, `sheets-${k}.svg`)), `sheet ${k}`);
  const dxf = runCli(['export', result, '--format', 'dxf', '--output', path.join(tmp, 'table.dxf')]);
  assert.equal(dxf.status, 0, dxf.stderr);
  assert.match(fs.readFileSync(path.join(tmp, 'table.dxf'), 'utf8'), /\$INSUNITS\n70\n4\n/);
  const small = runCli(['export', result, '--format', 'svg', '--sheet', '600x400', '--output', path.join(tmp, 'small.svg')]);
  assert.equal(small.status, 2);
  assert.match(small.stderr, /table-cut\.json: plate 1 \(1050 x 650 mm\) does not fit on a 600 x 400 mm sheet/);
  assert.equal(runCli(['export', result, '--format', 'svg', '--sheet', '600by400', '--output', path.join(tmp, 'bad.svg')]).status, 2);
  // Options that change nothing on cut sheets are refused, not silently ignored (issue 24).
  for (const [flag, value] of [['--voxel-size', '3'], ['--part', '2'], ['--clearance', '0.3']]) {
    const ignored = runCli(['export', result, '--format', 'svg', flag, value, '--output', path.join(tmp, 'ignored.svg')]);
    assert.equal(ignored.status, 2, `${flag}: ${ignored.stdout}`);
    assert.match(ignored.stderr, new RegExp(`table-cut\\.json: ${flag} does not apply to svg cut sheets`));
  }
  // And cut-sheet options on a mesh export (the registry: stl reads no sheet, kerf or spacing).
  for (const args of [['--kerf', '0.2'], ['--sheet', '600x400'], ['--spacing', '3'], ['--hairline']]) {
    const ignored = runCli(['export', result, '--format', 'stl', ...args, '--output', path.join(tmp, 'ignored.stl')]);
    assert.equal(ignored.status, 2, `${args[0]}: ${ignored.stdout}`);
    assert.match(ignored.stderr, new RegExp(`table-cut\\.json: ${args[0]} does not apply to stl`));
  }
});

test('export lists the formats of the core registry, the same as the package', async () => {
  const { loadDesiaModule } = await import('../../wasm/index.js');
  const core = await loadDesiaModule();
  const names = core.exportFormats().map((format) => format.name);
  assert.ok(names.includes('stl') && names.includes('svg') && names.includes('fpuz'), names.join(' '));
  const usage = runCli(['export']);
  assert.equal(usage.status, 2);
  assert.match(usage.stderr, new RegExp(`--format ${names.join('\\|')}\n`));
  const unknown = runCli(['export', path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), '--format', 'step', '--output', '/dev/null']);
  assert.equal(unknown.status, 2);
  assert.match(unknown.stderr, new RegExp(`unknown export format 'step' \\(expected one of: ${names.join(', ')};`));
});

test('the three design commands take the same search flags, with the same rules and messages', () => {
  const inputs = {
    voxel: ['--input', path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz'), '--parts', '3', '--output', '/tmp/x.puz'],
    plate: ['--input', 'examples/plate/table.json', '--output', '/tmp/x.json'],
    frame: ['--input', 'examples/frame/frame_cube.json', '--output', '/tmp/x.json'],
  };
  for (const [kind, args] of Object.entries(inputs)) {
    const negative = runCli(['design', kind, ...args, '--time-limit', '-1']);
    assert.equal(negative.status, 2, `${kind}: ${negative.stderr}`);
    assert.match(negative.stderr, /--time-limit expects a number of seconds >= 0, got '-1'/, kind);
    const noNodes = runCli(['design', kind, ...args, '--node-limit', '0']);
    assert.equal(noNodes.status, 2, kind);
    assert.match(noNodes.stderr, /--node-limit/, kind);
    const seed = runCli(['design', kind, ...args, '--seed', 'x']);
    assert.equal(seed.status, 2, kind);
    assert.match(seed.stderr, /--seed/, kind);
  }
});
