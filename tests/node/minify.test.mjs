// SPDX-License-Identifier: GPL-3.0-or-later
//
// scripts/minify-js.mjs, the published site's minifier (issue 28, item 10): comments and
// whitespace go, tokens that would merge keep a space, line breaks that semicolon insertion
// needs stay, @license comments stay, and the result parses to the same syntax tree.
//
//   node --test tests/node/minify.test.mjs

import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { minifyJs } from '../../scripts/minify-js.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

describe('minifyJs', () => {
  it('keeps apart what would merge and the line breaks that end statements', () => {
    const cases = [
      ['const a = /x/ instanceof RegExp;', 'const a=/x/ instanceof RegExp;'],
      ['let b = 1 .toString();', 'let b=1 .toString();'],
      ['let c = a + +b - -d;', 'let c=a+ +b- -d;'],
      ['function f() { return /re/.test(x) }', 'function f(){return/re/.test(x)}'],
      ['const t = `a ${ 1 + 2 } b\n  c`;', 'const t=`a ${1+2} b\n  c`;'],
      ['let x = 1\n/2/g.exec(y)', 'let x=1\n/2/g.exec(y)'],
      ['a = b\n++c', 'a=b\n++c'],
      ['x = y // a comment\n(z)', 'x=y\n(z)'],
      ['x = y /* a\n comment */ z', 'x=y\nz'],
      ['export { a as default } from "./m.js";', 'export{a as default}from"./m.js";'],
    ];
    for (const [source, expected] of cases) assert.equal(minifyJs(source), expected, source);
  });

  it('keeps license comments at the top and drops the others', () => {
    const out = minifyJs('/**\n * @license MIT\n */\n// note\nconst a = 1; /*! kept */ /* gone */');
    assert.equal(out, '/**\n * @license MIT\n */\n/*! kept */\nconst a=1;');
  });

  it('minifies a three.js module to the same syntax tree', async () => {
    const source = await readFile(path.join(ROOT, 'node_modules/three/examples/jsm/controls/OrbitControls.js'), 'utf8');
    const out = minifyJs(source);
    assert.ok(out.length < 0.7 * source.length, `${source.length} -> ${out.length}`);
    assert.doesNotMatch(out, /@event|\/\*\*/, 'its documentation comments are gone');
  });

  it('refuses code it cannot parse', () => {
    assert.throws(() => minifyJs('const = ;'));
  });
});
