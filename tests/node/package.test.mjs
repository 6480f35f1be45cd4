// SPDX-License-Identifier: GPL-3.0-or-later
// `npm pack` smoke test: the tarball holds what the package needs and nothing big or private,
// installs into an empty folder with no network (no hard dependencies), and works there when
// imported by name: a check and a seeded design equal to the native CLI's, and a failing input.
// In a checkout without the WebAssembly module, npm pack stops (prepack: scripts/prepack.mjs).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import { referenceDir, requireBuilt, root, runCli } from './support.mjs';

requireBuilt(path.join(root, 'dist/desia_wasm.wasm'), 'scripts/build.sh wasm');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-package-'));
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

function run(command, args, cwd) {
  const result = spawnSync(command, args, {
    cwd,
    encoding: 'utf8',
    maxBuffer: 64 << 20,
    // A private npm cache: nothing from the user's, nothing left behind in it.
    env: { ...process.env, npm_config_cache: path.join(tmp, 'npm-cache'), npm_config_update_notifier: 'false' },
  });
  if (result.error) throw result.error;
  assert.equal(result.status, 0, `${command} ${args.join(' ')} failed:\n${result.stdout}\n${result.stderr}`);
  return result.stdout;
}

const [packed] = JSON.parse(run('npm', ['pack', '--json', '--pack-destination', tmp], root));
const tarball = path.join(tmp, packed.filename);
const shipped = packed.files.map((file) => file.path);

test('the tarball holds the package and nothing else', () => {
  for (const file of ['package.json', 'README.md', 'LICENSE', 'wasm/index.js', 'wasm/index.d.ts', 'wasm/core.js', 'wasm/client.js', 'wasm/host.js', 'wasm/portfolio.js',
    'wasm/worker.js', 'dist/desia_wasm.js', 'dist/desia_wasm.wasm', 'dist/desia_light.js', 'dist/desia_light.wasm', 'web/viewer.js']) {
    assert.ok(shipped.includes(file), `${file} is missing from the tarball`);
  }
  for (const file of shipped) {
    assert.doesNotMatch(file, /^(build|build-[^/]*|tests|test-artifacts|third_party|node_modules|core|scripts|docs|examples|\.ci)\//, file);
    assert.doesNotMatch(file, /(^|\/)\.|\.tgz$|^web\/(index\.html|main\.js|sw\.js|worker\.js|style\.css)$/, file);
  }
  // Every relative import of a shipped module is shipped too (the viewer's sibling files).
  for (const file of shipped.filter((name) => name.endsWith('.js'))) {
    const source = fs.readFileSync(path.join(root, file), 'utf8');
    for (const [, specifier] of source.matchAll(/^\s*(?:import|export)\b[^'"]*?from\s+['"](\.{1,2}\/[^'"]+)['"]/gm)) {
      const target = path.posix.normalize(path.posix.join(path.posix.dirname(file), specifier));
      assert.ok(shipped.includes(target), `${file} imports ${specifier}, which is not in the tarball`);
    }
  }
  // The WebAssembly binaries (the full module and the light one) are by far the biggest files; the
  // whole package stays small.
  const sizes = Object.fromEntries(packed.files.map((file) => [file.path, file.size]));
  const modules = ['dist/desia_wasm.wasm', 'dist/desia_light.wasm'];
  for (const module of modules) {
    // The module itself, not an empty or stale stand-in: the one dist/ holds.
    assert.equal(sizes[module], fs.statSync(path.join(root, module)).size, `the packed ${module} is the built one`);
    assert.ok(sizes[module] > 100 * 1024, `the packed ${module} has ${sizes[module]} bytes`);
  }
  // A guard against files that do not belong, not a download budget (the wasm travels compressed:
  // docs/benchmarks.md, "The core's size against its speed"). 4 MiB until session 12, when the
  // core's plate joints (joints beside crossing plates, checked slots) took the package to 4.20 MB.
  assert.ok(packed.unpackedSize < 4.5 * 1024 * 1024, `unpacked size ${packed.unpackedSize}`);
  for (const [file, size] of Object.entries(sizes)) {
    if (!modules.includes(file)) assert.ok(size < 256 * 1024, `${file}: ${size} bytes`);
  }
  const manifest = JSON.parse(fs.readFileSync(path.join(root, 'package.json'), 'utf8'));
  assert.deepEqual(manifest.dependencies ?? {}, {}, 'no hard dependencies');
  assert.equal(manifest.peerDependenciesMeta?.three?.optional, true, 'three is an optional peer (the viewer only)');
  assert.deepEqual(manifest.exports['./viewer'], { types: './web/viewer.d.ts', default: './web/viewer.js' });
  assert.ok(shipped.includes('web/viewer.d.ts'), 'the viewer\'s types are shipped');
});

test('npm pack in a checkout without the WebAssembly module packs nothing and says how to build it', () => {
  // A checkout that was never built and cannot build (no scripts/build.sh): prepack must stop npm.
  const checkout = path.join(tmp, 'unbuilt');
  for (const file of [...shipped.filter((name) => !name.startsWith('dist/')), 'scripts/prepack.mjs']) {
    fs.mkdirSync(path.dirname(path.join(checkout, file)), { recursive: true });
    fs.copyFileSync(path.join(root, file), path.join(checkout, file));
  }
  const destination = path.join(tmp, 'unbuilt-packs');
  fs.mkdirSync(destination);
  const pack = () => spawnSync('npm', ['pack', '--json', '--pack-destination', destination], {
    cwd: checkout, encoding: 'utf8', env: { ...process.env, npm_config_cache: path.join(tmp, 'npm-cache'), npm_config_update_notifier: 'false' },
  });
  const missing = pack();
  assert.notEqual(missing.status, 0, 'npm pack succeeded without the module');
  assert.match(missing.stderr, /dist\/desia_wasm\.wasm \(missing\)/);
  assert.match(missing.stderr, /bash scripts\/build\.sh wasm/);
  // A file in its place that is not WebAssembly is no better.
  fs.mkdirSync(path.join(checkout, 'dist'));
  fs.writeFileSync(path.join(checkout, 'dist/desia_wasm.js'), '// not built\n');
  fs.writeFileSync(path.join(checkout, 'dist/desia_wasm.wasm'), 'not a module');
  const bogus = pack();
  assert.notEqual(bogus.status, 0, 'npm pack succeeded with a bogus module');
  assert.match(bogus.stderr, /dist\/desia_wasm\.wasm \(not a WebAssembly binary\)/);
  assert.deepEqual(fs.readdirSync(destination), [], 'a tarball was written');
  // In this (built) checkout the same step is silent: npm pack --json above printed only JSON.
  assert.equal(JSON.parse(fs.readFileSync(path.join(root, 'package.json'), 'utf8')).scripts.prepack, 'node scripts/prepack.mjs');
});

test("the viewer's declarations match what viewer.js exports and what mountViewer returns", () => {
  const source = fs.readFileSync(path.join(root, 'web/viewer.js'), 'utf8');
  const declarations = fs.readFileSync(path.join(root, 'web/viewer.d.ts'), 'utf8');
  const exported = (text, pattern) => [...text.matchAll(pattern)].map((match) => match[1]).sort();
  assert.deepEqual(exported(declarations, /^export (?:declare )?(?:function|class) (\w+)/gm),
    exported(source, /^export (?:function|class) (\w+)/gm));
  // The members of the handle object literal (4-space indented keys, getters and methods).
  const handleSource = source.slice(source.indexOf('const handle = {'), source.indexOf('mountedViewers.set(host, handle)'));
  const handleMembers = exported(handleSource, /^ {4}(?:get )?(\w+)\s*(?:\(|,|:)/gm);
  const handleType = declarations.slice(declarations.indexOf('interface ViewerHandle'), declarations.indexOf('export function mountViewer'));
  const declaredMembers = exported(handleType, /^ {2}(?:readonly )?(\w+)\s*[(:]/gm);
  assert.ok(handleMembers.length >= 10, `found only ${handleMembers}`);
  assert.deepEqual(declaredMembers, handleMembers);
});

test('installed from the tarball with no network, `desia` works in node by name', () => {
  const project = path.join(tmp, 'project');
  fs.mkdirSync(project);
  fs.writeFileSync(path.join(project, 'package.json'), JSON.stringify({ name: 'desia-smoke', private: true, type: 'module' }));
  run('npm', ['install', '--offline', '--no-audit', '--no-fund', tarball], project);
  assert.ok(fs.existsSync(path.join(project, 'node_modules/desia/dist/desia_wasm.wasm')));
  assert.ok(!fs.existsSync(path.join(project, 'node_modules/three')), 'the optional peer three is not installed');

  const k9File = path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz');
  const shapeFile = path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz');
  const designed = path.join(tmp, 'cube7.puz');
  assert.equal(runCli(['design', 'voxel', '--input', shapeFile, '--parts', '7', '--seed', '5', '--jobs', '1', '--output', designed]).status, 0);
  fs.writeFileSync(path.join(project, 'smoke.mjs'), `
import fs from 'node:fs';
import { createDesia, DesiaError, loadDesiaModule } from 'desia';
const out = { resolved: import.meta.resolve('desia') };
const desia = await createDesia();
out.version = desia.version();
out.report = await desia.check(fs.readFileSync(${JSON.stringify(k9File)}, 'utf8'), { source: ${JSON.stringify(k9File)} });
let progressCalls = 0;
const result = await desia.designVoxel(fs.readFileSync(${JSON.stringify(shapeFile)}, 'utf8'), { parts: 7, seed: 5, onProgress: () => progressCalls++ });
out.design = { status: result.status, puz: result.puz, progressCalls };
try {
  await desia.check('4 4 4\\n1 1 1 1\\n1 1\\n', { source: 'ragged.puz' });
  out.error = 'no error';
} catch (error) {
  out.error = { isDesiaError: error instanceof DesiaError, code: error.code, message: error.message };
}
out.stl = (await desia.exportAssembly(out.design.puz, { format: 'stl' })).byteLength;
out.sync = (await loadDesiaModule()).check(out.design.puz).interlocking;
await desia.terminate();
console.log(JSON.stringify(out));
`);
  const out = JSON.parse(run(process.execPath, ['smoke.mjs'], project));
  assert.equal(out.resolved, `file://${path.join(project, 'node_modules/desia/wasm/index.js')}`);
  assert.match(out.version, /^\d+\.\d+\.\d+$/);
  assert.deepEqual(out.report, JSON.parse(runCli(['check', k9File, '--json']).stdout));
  assert.equal(out.design.status, 'success');
  assert.equal(out.design.puz, fs.readFileSync(designed, 'utf8'));
  assert.ok(out.design.progressCalls >= 1);
  assert.deepEqual(out.error, { isDesiaError: true, code: 'bad-input', message: 'ragged.puz:3: row 2 of layer 1 has 2 values, expected Nx = 4' });
  assert.ok(out.stl > 84);
  assert.equal(out.sync, true);
});
