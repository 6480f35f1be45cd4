// SPDX-License-Identifier: GPL-3.0-or-later
// Every tolerance of the core is named once, with its unit and meaning, in
// core/include/desia/tolerances.h (issue 25). This test fails when a small-number literal (1e-9,
// 2.5e-3, 0.05) appears in the code of another file in core/: use or add a constant there. Comments
// and string literals are not code and may quote values.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { root } from './support.mjs';

const HOME = 'core/include/desia/tolerances.h';

// Literals that are not tolerances, each with its reason: file -> literal -> reason.
const ALLOWED = {
  'core/cli/frame_design_command.cpp': {
    '1e-9': 'the smallest --joint-size the command accepts (an input range with 1e9, not a tolerance)',
  },
  'core/io/voxel/voxel_export.cpp': {
    '1e-6': 'the smallest voxel size an export accepts (an input range with 1e6, printed in its error)',
  },
};

// The text with comments and string and character literals blanked (lines kept).
function codeOnly(text) {
  let out = '';
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    const next = text[i + 1];
    if (c === '/' && next === '/') {
      while (i < text.length && text[i] !== '\n') i++;
    } else if (c === '/' && next === '*') {
      i += 2;
      while (i < text.length && !(text[i] === '*' && text[i + 1] === '/')) out += text[i++] === '\n' ? '\n' : '';
      i += 2;
    } else if (c === 'R' && next === '"' && !/[A-Za-z0-9_]/.test(text[i - 1] ?? '')) {
      const open = text.indexOf('(', i);
      const close = `)${text.slice(i + 2, open)}"`;
      const end = text.indexOf(close, open);
      for (const ch of text.slice(i, end + close.length)) out += ch === '\n' ? '\n' : '';
      out += '""';
      i = end + close.length;
    } else if (c === '"' || (c === "'" && !/[0-9A-Fa-f]/.test(text[i - 1] ?? ''))) {
      // (a ' after a hex digit is a digit separator, as in 1'000)
      i++;
      while (i < text.length && text[i] !== c) i += text[i] === '\\' ? 2 : 1;
      i++;
      out += '""';
    } else {
      out += c;
      i++;
    }
  }
  return out;
}

function* coreFiles(folder) {
  for (const entry of fs.readdirSync(folder, { withFileTypes: true })) {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) yield* coreFiles(full);
    else if (/\.(cpp|h|hpp|cc)$/.test(entry.name)) yield full;
  }
}

// 1e-9, 2.5e-3, 1E-6 (optionally with a suffix), and decimals below 0.1: 0.05, 0.001.
const SMALL = /(?<![\w.])(\d+(?:\.\d+)?[eE]-\d+|0\.0\d*[1-9]\d*)[fFlL]?(?![\w.])/g;

test('no small-number literal in core/ outside desia/tolerances.h', () => {
  const found = [];
  const used = new Set();
  for (const file of coreFiles(path.join(root, 'core'))) {
    const relative = path.relative(root, file).split(path.sep).join('/');
    if (relative === HOME) continue;
    const lines = codeOnly(fs.readFileSync(file, 'utf8')).split('\n');
    lines.forEach((line, index) => {
      for (const match of line.matchAll(SMALL)) {
        const literal = match[1];
        if (ALLOWED[relative]?.[literal]) {
          used.add(`${relative} ${literal}`);
          continue;
        }
        found.push(`${relative}:${index + 1}: ${literal} (name it in ${HOME})`);
      }
    });
  }
  assert.deepEqual(found, []);
  const stale = Object.entries(ALLOWED).flatMap(([file, literals]) =>
    Object.keys(literals).filter((literal) => !used.has(`${file} ${literal}`)).map((literal) => `${file} ${literal}`));
  assert.deepEqual(stale, [], 'allowed literals no longer in the code: take them off the list');
});

test('every tolerance in desia/tolerances.h says what it measures', () => {
  const lines = fs.readFileSync(path.join(root, HOME), 'utf8').split('\n');
  const bare = [];
  lines.forEach((line, index) => {
    if (!/^constexpr double k\w+ = /.test(line)) return;
    if (!lines[index - 1]?.startsWith('//')) bare.push(line);
  });
  assert.deepEqual(bare, []);
});
