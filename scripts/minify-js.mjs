// SPDX-License-Identifier: GPL-3.0-or-later
//
// A safe, dependency-free JavaScript minifier for the published site (scripts/build-site.mjs):
// it removes comments and collapses whitespace, nothing else (no renaming, no rewriting). Every
// token is copied byte for byte from the source; between two tokens it keeps a line break where
// the source had one (so automatic semicolon insertion behaves the same) and a single space only
// where the tokens would otherwise merge (`a in`, `+ +x`, `1 .x`). Comments with `@license` or
// `/*!` are kept at the top. The result is checked: its syntax tree must equal the source's,
// position fields aside, or the function throws.
//
// Tokens come from acorn, the ECMAScript parser Emscripten needs (Debian's node-acorn, installed
// with emscripten by scripts/setup.sh). three.js 0.187 ships no minified build; this takes its
// 2.1 MB of modules to 1.1 MB (brotli: 314 KB to 183 KB).

import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const ACORN_PATHS = ['acorn', '/usr/share/nodejs/acorn'];

let acorn = null;
function loadAcorn() {
  if (acorn) return acorn;
  for (const candidate of ACORN_PATHS) {
    try {
      if (candidate.startsWith('/') && !existsSync(candidate)) continue;
      acorn = require(candidate);
      return acorn;
    } catch {
      // try the next place
    }
  }
  throw new Error('acorn is missing (Debian package node-acorn, which emscripten pulls in: bash scripts/setup.sh)');
}

const OPTIONS = { ecmaVersion: 'latest', sourceType: 'module', allowHashBang: true };
const IDENTIFIER_PART = /[\p{ID_Continue}$\\\u200c\u200d]/u;
const LINE_BREAK = /[\n\r\u2028\u2029]/;

/** Whether two adjacent pieces of code need a space between them to stay two tokens. */
function needsSpace(previous, previousToken, next) {
  const a = previous[previous.length - 1];
  const b = next[0];
  if (IDENTIFIER_PART.test(a) && IDENTIFIER_PART.test(b)) return true;
  if ((a === '+' || a === '-') && b === a) return true; // a + +b, a - -b
  if (a === '/' && (b === '/' || b === '*')) return true; // a / /re/
  if (a === '<' && b === '!') return true; // <!-- (an HTML comment in scripts)
  if (a === '-' && b === '>') return true; // -->
  if (previousToken.type.label === 'num' && b === '.') return true; // 1 .toString()
  if (previousToken.type.label === 'regexp' && IDENTIFIER_PART.test(b)) return true; // /x/ instanceof
  return false;
}

/** `source` with comments and needless whitespace removed; throws if the meaning could change. */
export function minifyJs(source) {
  const { tokenizer, parse } = loadAcorn();
  const kept = [];
  const onComment = (block, text) => {
    if (block && (text.startsWith('!') || text.includes('@license'))) kept.push(`/*${text}*/`);
  };
  const parts = [];
  let last = '';
  let previousToken = null;
  for (const token of tokenizer(source, { ...OPTIONS, onComment })) {
    const text = source.slice(token.start, token.end);
    if (previousToken !== null && token.start > previousToken.end) {
      // A comment spanning lines counts as a line break for semicolon insertion.
      const gap = source.slice(previousToken.end, token.start);
      if (LINE_BREAK.test(gap)) {
        parts.push('\n');
        last = '\n';
      } else if (needsSpace(last, previousToken, text)) {
        parts.push(' ');
        last = ' ';
      }
    }
    parts.push(text);
    if (text.length > 0) last = text;
    previousToken = token;
  }
  const out = (kept.length > 0 ? `${kept.join('\n')}\n` : '') + parts.join('');
  assertSameTree(parse(source, OPTIONS), parse(out, OPTIONS));
  return out;
}

const POSITION_KEYS = new Set(['start', 'end', 'loc', 'range']);

/** Throws unless the two syntax trees are equal apart from source positions. */
function assertSameTree(a, b) {
  // Each entry: two values and where they are (a chain of { up, key, node } built only as needed).
  const stack = [[a, b, null]];
  const fail = (what, where) => {
    const names = [];
    for (let at = where; at; at = at.up) names.push(at.node?.type ? `${at.key}(${at.node.type}@${at.node.start})` : at.key);
    throw new Error(`minifyJs: the minified code ${what} at ${names.reverse().join('.') || 'the top'}`);
  };
  while (stack.length > 0) {
    const [x, y, where] = stack.pop();
    if (x === y) continue;
    if (x instanceof RegExp && y instanceof RegExp) {
      if (String(x) !== String(y)) fail('has another regular expression', where);
      continue;
    }
    if (typeof x !== 'object' || typeof y !== 'object' || x === null || y === null) {
      if (Number.isNaN(x) && Number.isNaN(y)) continue;
      fail(`means something else (${String(x)} vs ${String(y)})`, where);
    }
    let count = 0;
    for (const key in x) {
      if (POSITION_KEYS.has(key)) continue;
      count += 1;
      stack.push([x[key], y[key], { up: where, key, node: x }]);
    }
    for (const key in y) if (!POSITION_KEYS.has(key)) count -= 1;
    if (count !== 0) fail('has another shape', where);
  }
}
