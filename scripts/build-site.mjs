#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the playground as a self-contained static site (`bash scripts/build.sh site`, which
// builds the WebAssembly module first):
//
//   node scripts/build-site.mjs [--out dist/site]
//
//   index.html, *.js, style.css   the playground (web/) and its offline service worker
//   wasm/*.js                     the package the playground runs on (createDesia) and its worker
//   dist/desia_wasm.{js,wasm}     the WebAssembly core (full: every kind)
//   dist/desia_light.{js,wasm}    the light core the worker loads first (voxels, contacts, meshes)
//   examples/                     the example folders the playground lists, and embed.html
//   vendor/three/                 the three.js modules the pages import (and three's LICENSE)
//
// The development layout is left alone: files are copied, and every relative or root-absolute
// URL in them is rewritten for the new layout (web/ becomes the site's root, node_modules/three/
// becomes vendor/three/), always as a RELATIVE URL, so the folder works at any path of any static
// host (https://example.org/desia/ as well as /). Inline scripts whose text changes get their
// Content-Security-Policy hash recomputed. The build fails when a file refers to something the
// site does not contain, or when a listed example is missing.
//
// For a light first visit, every JavaScript file is then minified (comments and whitespace only,
// checked to parse to the same syntax tree: scripts/minify-js.mjs; three.js ships no minified
// build) and every file gets precompressed copies beside it, `x.br` (brotli) and `x.gz` (gzip),
// which hosts that support them send to browsers that accept them (docs/playground.md; the
// development server does: node scripts/serve.mjs --root dist/site). `--no-minify` keeps the
// JavaScript as written. Prints the size on its last line.

import { createHash } from 'node:crypto';
import { promisify } from 'node:util';
import zlib from 'node:zlib';
import { existsSync, readFileSync } from 'node:fs';
import { cp, mkdir, readdir, readFile, rename, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { minifyJs } from './minify-js.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const DEFAULT_OUT = path.join(ROOT, 'dist/site');
const posix = path.posix;

/** Where each part of the repository goes in the site (repository path prefix → site prefix). */
const LAYOUT = [
  ['web/', ''],
  ['wasm/', 'wasm/'],
  ['dist/', 'dist/'],
  ['examples/', 'examples/'],
  ['node_modules/three/', 'vendor/three/'],
];
/** Example files worth serving (the scripts that made them stay behind). */
const EXAMPLE_EXTENSIONS = new Set(['.puz', '.json', '.obj', '.stl', '.fpuz', '.txt', '.md']);
const WEB_EXTENSIONS = new Set(['.js', '.css', '.html']);

class SiteError extends Error {}

function siteTargetOf(repoPath) {
  for (const [from, to] of LAYOUT) {
    if (repoPath.startsWith(from)) return to + repoPath.slice(from.length);
  }
  return null;
}

/**
 * Rewrites the URL `spec` written in repository file `repoFile` for its copy at `siteFile`:
 * relative and root-absolute URLs into the repository become relative URLs into the site.
 * Returns null for URLs this build does not touch (bare specifiers, data:, other origins).
 */
function relocate(spec, repoFile, siteFile, references) {
  let repoTarget;
  if (spec.startsWith('./') || spec.startsWith('../')) {
    repoTarget = posix.normalize(posix.join(posix.dirname(repoFile), spec));
  } else if (spec.startsWith('/') && !spec.startsWith('//')) {
    repoTarget = spec.slice(1);
  } else {
    return null;
  }
  if (spec.endsWith('/') && !repoTarget.endsWith('/')) repoTarget += '/';
  const siteTarget = siteTargetOf(repoTarget);
  if (siteTarget === null || repoTarget.startsWith('../')) {
    throw new SiteError(`${repoFile} refers to ${spec} (${repoTarget}), which the site does not contain`);
  }
  references.push({ from: siteFile, spec, target: siteTarget, repoTarget });
  let relative = posix.relative(posix.dirname(siteFile), siteTarget.replace(/\/$/, '')) || '.';
  if (siteTarget === '' || siteTarget.endsWith('/')) relative += '/';
  return relative.startsWith('.') ? relative : `./${relative}`;
}

/** Relative URLs in quotes ('./x.js', "../wasm/core.js", `../examples/voxel/`). */
const RELATIVE_LITERAL = /(['"`])(\.{1,2}\/[^'"`\s]*)\1/g;
/** Root-absolute URLs into the repository in quotes ("/node_modules/three/…"): HTML only. */
const ABSOLUTE_LITERAL = /(['"])(\/(?:node_modules|web|wasm|dist|examples)\/[^'"\s]*)\1/g;

function rewriteUrls(text, repoFile, siteFile, references, { absolute }) {
  const replace = (match, quote, spec) => {
    const moved = relocate(spec, repoFile, siteFile, references);
    return moved === null ? match : `${quote}${moved}${quote}`;
  };
  let out = text.replace(RELATIVE_LITERAL, replace);
  if (absolute) out = out.replace(ABSOLUTE_LITERAL, replace);
  return out;
}

const sha256 = (text) => createHash('sha256').update(text, 'utf8').digest('base64');
const INLINE_BLOCK = /<(script|style)\b([^>]*)>([\s\S]*?)<\/\1>/gi;

/** The text of each inline script and style (those a CSP hash allows). */
function inlineBlocks(html) {
  return [...html.matchAll(INLINE_BLOCK)]
    .filter(([, , attributes, body]) => !/\bsrc\s*=/.test(attributes) && body.length > 0)
    .map(([, , , body]) => body);
}

function rewriteHtml(html, repoFile, siteFile, references) {
  const before = inlineBlocks(html);
  let out = rewriteUrls(html, repoFile, siteFile, references, { absolute: true });
  const after = inlineBlocks(out);
  if (before.length !== after.length) throw new SiteError(`${repoFile}: rewriting changed its inline blocks`);
  const policy = /<meta\s+http-equiv="Content-Security-Policy"/i.test(out);
  for (let i = 0; i < before.length; i += 1) {
    if (before[i] === after[i]) continue;
    const [oldHash, newHash] = [sha256(before[i]), sha256(after[i])];
    if (!policy) continue;
    if (!out.includes(`'sha256-${oldHash}'`)) {
      throw new SiteError(`${repoFile}: its Content-Security-Policy lacks the hash of inline block ${i + 1} ('sha256-${oldHash}'): fix the page first`);
    }
    out = out.replaceAll(`'sha256-${oldHash}'`, `'sha256-${newHash}'`);
  }
  return out;
}

/** Bare three.js specifiers imported by a module ('three', 'three/addons/…'). */
function threeSpecifiers(source) {
  const found = new Set();
  for (const [, spec] of source.matchAll(/\b(?:from|import)\s*\(?\s*['"](three(?:\/[^'"]*)?)['"]/g)) found.add(spec);
  return found;
}

/** three's package path for a bare specifier, through its package.json "exports". */
function resolveThree(spec, exportsMap) {
  const sub = spec === 'three' ? '.' : `./${spec.slice('three/'.length)}`;
  const exact = exportsMap[sub];
  if (exact) return posix.normalize(typeof exact === 'string' ? exact : exact.import ?? exact.default);
  for (const [pattern, target] of Object.entries(exportsMap)) {
    if (pattern.endsWith('/*') && sub.startsWith(pattern.slice(0, -1)) && typeof target === 'string') {
      return posix.normalize(target.replace('*', sub.slice(pattern.length - 1)));
    }
  }
  throw new SiteError(`cannot resolve ${spec} in node_modules/three/package.json`);
}

async function listFiles(dir, base = dir) {
  const out = [];
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...await listFiles(full, base));
    else if (entry.isFile()) out.push(path.relative(base, full).split(path.sep).join('/'));
  }
  return out.sort();
}

function parseArguments(argv) {
  let out = DEFAULT_OUT;
  let minify = true;
  for (let i = 0; i < argv.length; i += 1) {
    if (argv[i] === '--out') out = argv[++i];
    else if (argv[i].startsWith('--out=')) out = argv[i].slice('--out='.length);
    else if (argv[i] === '--no-minify') minify = false;
    else throw new SiteError(`unknown argument ${argv[i]} (usage: node scripts/build-site.mjs [--out DIR] [--no-minify])`);
  }
  if (!out) throw new SiteError('--out needs a folder');
  return { out: path.resolve(out), minify };
}

const brotli = promisify(zlib.brotliCompress);
const gzip = promisify(zlib.gzip);
/** The precompressed copies written beside each file: suffix → compressor (best settings). */
const PRECOMPRESSED = [
  ['.br', (bytes) => brotli(bytes, {
    params: { [zlib.constants.BROTLI_PARAM_QUALITY]: zlib.constants.BROTLI_MAX_QUALITY, [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length },
  })],
  ['.gz', (bytes) => gzip(bytes, { level: zlib.constants.Z_BEST_COMPRESSION })],
];

/**
 * Minifies the site's JavaScript in place (unless `minify` is false), then writes `x.br` and
 * `x.gz` beside every file `x` (a copy that would not be smaller is left out, so a host sends
 * the file itself). Returns the bytes of the files and of each compressed set.
 */
async function finishFiles(dir, files, { minify }) {
  const totals = { bytes: 0, '.br': 0, '.gz': 0, compressedFiles: 0 };
  for (const file of files) {
    const full = path.join(dir, file);
    let bytes = await readFile(full);
    if (minify && file.endsWith('.js')) {
      bytes = Buffer.from(minifyJs(bytes.toString('utf8')), 'utf8');
      await writeFile(full, bytes);
    }
    totals.bytes += bytes.length;
    for (const [suffix, compress] of PRECOMPRESSED) {
      const packed = await compress(bytes);
      if (packed.length < bytes.length) {
        await writeFile(full + suffix, packed);
        totals[suffix] += packed.length;
        totals.compressedFiles += 1;
      } else {
        totals[suffix] += bytes.length;
      }
    }
  }
  return totals;
}

/**
 * Builds the site into `out`; returns { files, bytes, brotliBytes, gzipBytes } (the files
 * themselves, without the precompressed copies; their sizes as a browser would receive them).
 */
export async function buildSite(out = DEFAULT_OUT, { minify = true } = {}) {
  for (const [file, fix] of [
    ['dist/desia_wasm.js', 'bash scripts/build.sh wasm'], ['dist/desia_wasm.wasm', 'bash scripts/build.sh wasm'],
    ['dist/desia_light.js', 'bash scripts/build.sh wasm'], ['dist/desia_light.wasm', 'bash scripts/build.sh wasm'],
    ['node_modules/three/package.json', 'bash scripts/setup.sh (installs three from the npm registry)'],
  ]) {
    if (!existsSync(path.join(ROOT, file))) throw new SiteError(`${file} is missing: run ${fix}`);
  }
  // Never wipe a folder that is not a site built here.
  if (existsSync(out) && (await readdir(out)).length > 0
    && !['index.html', 'sw.js', 'main.js'].every((file) => existsSync(path.join(out, file)))) {
    throw new SiteError(`${out} exists and does not look like a built site: refusing to replace it`);
  }
  const staging = `${out}.partial-${process.pid}`;
  await rm(staging, { recursive: true, force: true });
  await mkdir(staging, { recursive: true });
  const references = [];
  const write = async (siteFile, content) => {
    const full = path.join(staging, siteFile);
    await mkdir(path.dirname(full), { recursive: true });
    await writeFile(full, content);
  };
  const copy = async (repoFile, siteFile) => {
    const full = path.join(staging, siteFile);
    await mkdir(path.dirname(full), { recursive: true });
    await cp(path.join(ROOT, repoFile), full);
  };
  try {
    // The playground: web/ becomes the root of the site.
    const webFiles = (await readdir(path.join(ROOT, 'web')))
      .filter((file) => WEB_EXTENSIONS.has(path.extname(file)) && !file.endsWith('.d.ts')).sort();
    const modules = [];
    for (const file of webFiles) {
      const repoFile = `web/${file}`;
      const text = await readFile(path.join(ROOT, repoFile), 'utf8');
      if (file.endsWith('.html')) await write(file, rewriteHtml(text, repoFile, file, references));
      else if (file.endsWith('.js')) {
        const rewritten = rewriteUrls(text, repoFile, file, references, { absolute: false });
        modules.push(rewritten);
        await write(file, rewritten);
      } else await write(file, text);
    }
    // The package's loader and host (the worker imports them) and the core.
    for (const file of (await readdir(path.join(ROOT, 'wasm'))).filter((name) => name.endsWith('.js')).sort()) {
      await copy(`wasm/${file}`, `wasm/${file}`);
      modules.push(await readFile(path.join(ROOT, 'wasm', file), 'utf8'));
    }
    await copy('dist/desia_wasm.js', 'dist/desia_wasm.js');
    await copy('dist/desia_wasm.wasm', 'dist/desia_wasm.wasm');
    await copy('dist/desia_light.js', 'dist/desia_light.js');
    await copy('dist/desia_light.wasm', 'dist/desia_light.wasm');

    // The embed example: a plain page using the drop-in viewer.
    const embed = await readFile(path.join(ROOT, 'examples/embed.html'), 'utf8');
    await write('examples/embed.html', rewriteHtml(embed, 'examples/embed.html', 'examples/embed.html', references));

    // Every example folder the pages refer to, with its data files.
    const exampleDirs = new Set(references.filter(({ target }) => /^examples\/[^/]+\//.test(target))
      .map(({ target }) => target.split('/')[1]));
    const shipped = new Set();
    for (const dir of [...exampleDirs].sort()) {
      const source = path.join(ROOT, 'examples', dir);
      if (!existsSync(source)) throw new SiteError(`the playground refers to examples/${dir}/, which does not exist`);
      for (const file of await listFiles(source)) {
        if (!EXAMPLE_EXTENSIONS.has(path.extname(file).toLowerCase())) continue;
        await copy(`examples/${dir}/${file}`, `examples/${dir}/${file}`);
        shipped.add(path.basename(file));
      }
    }
    // The examples the playground lists ({ file: '…' } in its modules) are all there.
    const listed = new Set(modules.flatMap((source) => [...source.matchAll(/\bfile:\s*'([^'\/]+\.\w+)'/g)].map((match) => match[1])));
    const missing = [...listed].filter((file) => !shipped.has(file));
    if (missing.length > 0) throw new SiteError(`the playground lists examples that are not in examples/: ${missing.join(', ')}`);

    // three.js: the modules imported by bare specifier, and theirs, relative to build/.
    const threeRoot = path.join(ROOT, 'node_modules/three');
    const threeExports = JSON.parse(readFileSync(path.join(threeRoot, 'package.json'), 'utf8')).exports;
    const queue = [...new Set(modules.flatMap((source) => [...threeSpecifiers(source)]))].map((spec) => resolveThree(spec, threeExports));
    const vendored = new Set();
    while (queue.length > 0) {
      const file = queue.pop();
      if (vendored.has(file)) continue;
      if (!existsSync(path.join(threeRoot, file))) throw new SiteError(`node_modules/three/${file} is missing: run npm ci`);
      vendored.add(file);
      await copy(`node_modules/three/${file}`, `vendor/three/${file}`);
      const source = await readFile(path.join(threeRoot, file), 'utf8');
      for (const spec of threeSpecifiers(source)) queue.push(resolveThree(spec, threeExports));
      for (const [, spec] of source.matchAll(/\b(?:from|import)\s*\(?\s*['"](\.{1,2}\/[^'"]+)['"]/g)) {
        queue.push(posix.normalize(posix.join(posix.dirname(file), spec)));
      }
    }
    await copy('node_modules/three/LICENSE', 'vendor/three/LICENSE');

    // Every rewritten reference to a file of the repository points at one the site has (names
    // the repository has no file for, like the service worker's state entries, are not files).
    const files = await listFiles(staging);
    const present = new Set(files);
    const isFolder = (target) => target === '' || target.endsWith('/');
    const dangling = references.filter(({ target, repoTarget }) => !isFolder(target) && !present.has(target)
      && existsSync(path.join(ROOT, repoTarget)));
    if (dangling.length > 0) {
      throw new SiteError(`references to files the site lacks: ${dangling.map(({ from, spec }) => `${from}: ${spec}`).join(', ')}`);
    }
    // The import maps' prefixes, too.
    const prefixes = references.filter(({ target }) => target.endsWith('/'));
    for (const { from, spec, target } of prefixes) {
      if (!files.some((file) => file.startsWith(target))) throw new SiteError(`${from}: ${spec} names an empty folder of the site`);
    }

    const totals = await finishFiles(staging, files, { minify });
    await rm(out, { recursive: true, force: true });
    await mkdir(path.dirname(out), { recursive: true });
    await rename(staging, out);
    return { files: files.length, bytes: totals.bytes, brotliBytes: totals['.br'], gzipBytes: totals['.gz'] };
  } catch (error) {
    await rm(staging, { recursive: true, force: true });
    throw error;
  }
}

async function main() {
  try {
    const { out, minify } = parseArguments(process.argv.slice(2));
    const { files, bytes, brotliBytes, gzipBytes } = await buildSite(out, { minify });
    const shown = path.relative(process.cwd(), out) || '.';
    const mb = (n) => (n / 1e6).toFixed(2);
    console.log(`${shown.startsWith('..') ? out : shown}: ${files} files, ${(bytes / 1e6).toFixed(1)} MB (${bytes} bytes; `
      + `brotli ${mb(brotliBytes)} MB, gzip ${mb(gzipBytes)} MB, precompressed beside each file)`);
  } catch (error) {
    console.error(`build-site: ${error instanceof SiteError ? error.message : error.stack}`);
    process.exit(1);
  }
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) main();
