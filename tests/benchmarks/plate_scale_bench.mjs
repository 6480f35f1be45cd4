// SPDX-License-Identifier: GPL-3.0-or-later
// How plate designs scale (issue 24): LONG TABLEs of 102 to 9,998 plates (long_table(bays) of
// examples/plate/make_examples.py) designed by the CLI with planned and cut joints, then checked
// as written. Whole processes are timed (wall and user seconds) with their peak memory (GNU time's
// maximum resident set), so reading, the search, the cut, the verification and writing all count.
// The largest runs under --time-limit and shows that the limit bounds the whole command.
//
//   node tests/benchmarks/plate_scale_bench.mjs [--largest BAYS] [--time-limit SECONDS]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../', import.meta.url));
const cli = process.env.DESIA_CLI ?? path.join(root, 'build/native/core/cli/desia');
const option = (name, fallback) => {
  const at = process.argv.indexOf(name);
  return at > 0 ? Number(process.argv[at + 1]) : fallback;
};
const largest = option('--largest', 2499);
const timeLimit = option('--time-limit', 60);
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-plate-scale-'));

function longTable(bays) {
  const file = path.join(scratch, `long_table_${bays}.json`);
  const script = `import json, sys; sys.path.insert(0, ${JSON.stringify(path.join(root, 'examples/plate'))})
import make_examples as m; json.dump(m.long_table(${bays}), open(${JSON.stringify(file)}, 'w'))`;
  const made = spawnSync('python3', ['-c', script], { encoding: 'utf8' });
  if (made.status !== 0) throw new Error(`python3 could not make the long table: ${made.stderr}`);
  return file;
}

// Runs the CLI under GNU time: { status, wall, user, megabytes, stderr }.
function timed(args) {
  const run = spawnSync('/usr/bin/time', ['-f', 'TIME %e %U %M', cli, ...args], { encoding: 'utf8' });
  const line = run.stderr.split('\n').find((l) => l.startsWith('TIME '));
  if (!line) throw new Error(`no timing from /usr/bin/time (is GNU time installed?): ${run.stderr}`);
  const [, wall, user, kilobytes] = line.split(' ');
  return { status: run.status, wall: Number(wall), user: Number(user), megabytes: Number(kilobytes) / 1024, stderr: run.stderr };
}

const rows = [];
for (const bays of [25, 100, 250, largest]) {
  const input = longTable(bays);
  const plates = JSON.parse(fs.readFileSync(input, 'utf8')).plates.length;
  for (const joints of ['planned', 'cut']) {
    const output = path.join(scratch, `result_${bays}_${joints}.json`);
    const limit = bays === largest ? timeLimit : 600;
    const design = timed(['design', 'plate', '--input', input, '--joints', joints, '--time-limit', String(limit), '--output', output, '--quiet']);
    const written = design.status === 0;
    const check = written ? timed(['check', output]) : null;
    rows.push({ plates, joints, limit, design, check, bytes: written ? fs.statSync(output).size : 0 });
    if (bays === largest) break;  // one run under the limit is the point
  }
}

console.log('| plates | joints | design (wall / user) | peak memory | result | check (wall / user) | check peak |');
console.log('| ---: | --- | ---: | ---: | --- | ---: | ---: |');
for (const { plates, joints, limit, design, check, bytes } of rows) {
  const outcome = design.status === 0 ? `${(bytes / 1e6).toFixed(1)} MB written` : `exit ${design.status} (--time-limit ${limit})`;
  const checked = check ? `${check.wall.toFixed(2)} s / ${check.user.toFixed(2)} s` : '—';
  const checkPeak = check ? `${check.megabytes.toFixed(0)} MB` : '—';
  console.log(`| ${plates} | ${joints} | ${design.wall.toFixed(2)} s / ${design.user.toFixed(2)} s | ${design.megabytes.toFixed(0)} MB | ${outcome} | ${checked} | ${checkPeak} |`);
}
fs.rmSync(scratch, { recursive: true, force: true });
