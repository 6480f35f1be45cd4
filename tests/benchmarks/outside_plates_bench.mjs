// SPDX-License-Identifier: GPL-3.0-or-later
// Plate designs no one here made (issue 26's goal: of real timber-plate designs from outside, at
// least 4 in 5 designed with made joints, the rest refused with the reason named). The set is the
// plate dataset of IBOIS's joinery solver (github.com/petrasvestartas/wood, cmake/src/wood/dataset,
// `type_plates_name_*.xml`: each plate as the pair of its two face outlines, in mm). Its licence
// forbids commercial use, so it is not copied into this repository: the script clones it (pinned
// commit) into a cache folder, or reads a folder given with --dataset.
//
// Each file is converted to a desia plate document (plate k = polylines 2k and 2k+1, the closing
// point dropped), then `desia design plate` runs with the default joints (auto) under the time
// limit, and the result, if any, is checked again as written. One row per file: plates, what
// desia answered (cut / milled / planned joints, or the refusal's reason), seconds.
//
//   node tests/benchmarks/outside_plates_bench.mjs [--dataset DIR] [--time-limit SECONDS] [--max-plates N]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../', import.meta.url));
const cli = process.env.DESIA_CLI ?? path.join(root, 'build/native/core/cli/desia');
const WOOD_REPOSITORY = 'https://github.com/petrasvestartas/wood.git';
const WOOD_COMMIT = '8b19fb96d0999d0e2de1d89251031809df9e0346';
const argument = (name, fallback) => {
  const at = process.argv.indexOf(name);
  return at > 0 ? process.argv[at + 1] : fallback;
};
const timeLimit = Number(argument('--time-limit', 60));
const maxPlates = Number(argument('--max-plates', 150));

function datasetFolder() {
  const given = argument('--dataset', null);
  if (given) return given;
  const cache = path.join(os.homedir(), '.cache', 'desia', 'wood');
  if (!fs.existsSync(path.join(cache, '.git'))) {
    const cloned = spawnSync('git', ['clone', '--quiet', '--filter=blob:none', '--no-checkout', WOOD_REPOSITORY, cache], { stdio: 'inherit' });
    if (cloned.status !== 0) throw new Error(`could not clone ${WOOD_REPOSITORY}: give a copy with --dataset DIR`);
  }
  const checkedOut = spawnSync('git', ['-C', cache, 'checkout', '--quiet', WOOD_COMMIT, '--', 'cmake/src/wood/dataset'], { stdio: 'inherit' });
  if (checkedOut.status !== 0) throw new Error(`could not check out ${WOOD_COMMIT} in ${cache}`);
  return path.join(cache, 'cmake/src/wood/dataset');
}

// The dataset's XML: <Polyline><point><x>…</x><y>…</y><z>…</z></point>…</Polyline>, closed.
function polylinesOf(xml) {
  return [...xml.matchAll(/<Polyline>([\s\S]*?)<\/Polyline>/g)].map(([, body]) => {
    const points = [...body.matchAll(/<x>([^<]+)<\/x>\s*<y>([^<]+)<\/y>\s*<z>([^<]+)<\/z>/g)].map((m) => m.slice(1, 4).map(Number));
    const [first, last] = [points[0], points[points.length - 1]];
    if (points.length > 1 && first.every((value, k) => value === last[k])) points.pop();
    return points;
  });
}

function plateDocument(name, polylines) {
  const plates = [];
  for (let k = 0; k + 1 < polylines.length; k += 2) plates.push({ id: k / 2 + 1, faces: [polylines[k], polylines[k + 1]] });
  return { format: 'desia-assembly', version: 1, kind: 'plate', name, plates };
}

// What desia answered, in a few words: the joints of a result, or the first reason it refused.
function answer(run) {
  const text = `${run.stdout}\n${run.stderr}`.replace(/\s+/g, ' ');
  if (run.status === 0) return `**${/joints: (\w+)/.exec(text)?.[1] ?? '?'}**`;
  const reason = /error: [^:]+: (.*)$/.exec(text)?.[1] ?? /desia: [^:]+: (.*)$/.exec(text)?.[1] ?? text;
  return `exit ${run.status}: ${reason.slice(0, 140)}${reason.length > 140 ? '…' : ''}`;
}

const folder = datasetFolder();
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-outside-plates-'));
const rows = [];
for (const file of fs.readdirSync(folder).filter((f) => /^type_plates_name_.*\.xml$/.test(f)).sort()) {
  const name = file.replace(/^type_plates_name_/, '').replace(/\.xml$/, '');
  const document = plateDocument(name, polylinesOf(fs.readFileSync(path.join(folder, file), 'utf8')));
  if (document.plates.length === 0 || document.plates.length > maxPlates) continue;
  const input = path.join(scratch, `${name}.json`);
  const output = path.join(scratch, `${name}.result.json`);
  fs.writeFileSync(input, JSON.stringify(document));
  const start = process.hrtime.bigint();
  const design = spawnSync(cli, ['design', 'plate', '--input', input, '--output', output, '--time-limit', String(timeLimit)], { encoding: 'utf8' });
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  const check = design.status === 0 ? spawnSync(cli, ['check', output], { encoding: 'utf8' }) : null;
  rows.push({ name, plates: document.plates.length, design, seconds, checked: check ? check.status === 0 : null });
  process.stderr.write(`${name}: ${answer(design)}\n`);
}

console.log(`| design | plates | desia's answer | seconds | result checked again |`);
console.log('| --- | ---: | --- | ---: | --- |');
for (const { name, plates, design, seconds, checked } of rows) {
  console.log(`| ${name} | ${plates} | ${answer(design).replace(/\|/g, '/')} | ${seconds.toFixed(1)} | ${checked === null ? '' : checked ? 'passes' : '**FAILS**'} |`);
}
const said = (design) => `${design.stdout}\n${design.stderr}`;
const made = rows.filter(({ design }) => design.status === 0 && /joints: (cut|milled)/.test(said(design))).length;
const planned = rows.filter(({ design }) => design.status === 0 && /joints: planned/.test(said(design))).length;
console.log(`\n${rows.length} designs: ${made} with made joints (cut or milled), ${planned} with the paper's plan only, ` +
  `${rows.length - made - planned} refused (time limit ${timeLimit} s).`);
