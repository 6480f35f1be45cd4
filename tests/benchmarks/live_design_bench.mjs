#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design's frame rate (issue 28, item 8; docs/benchmarks.md "Live design"): the playground in
// headless Chromium (SwiftShader WebGL) designs the bunny with N = 140 on two workers and, for
// the first `--seconds` (5) of the run, counts the frames the page managed, the long tasks
// (main-thread tasks over 50 ms), the frames the 3D view drew and the shader programs three.js
// holds; one line per run (seeds 1, 2, ...), then the medians. Needs dist/ (bash
// scripts/build.sh wasm) and Chromium (as the browser tests).
//
//   node tests/benchmarks/live_design_bench.mjs [--parts 140] [--workers 2] [--seconds 5] [--runs 3] [--width 1400 --height 900]

import { parseArgs } from 'node:util';
import { openBrowser, showDesignSettings, waitForReady } from '../browser/support.mjs';
import { measureLiveDesign } from '../browser/live-frames.mjs';

const { values } = parseArgs({
  options: {
    parts: { type: 'string', default: '140' },
    workers: { type: 'string', default: '2' },
    seconds: { type: 'string', default: '5' },
    runs: { type: 'string', default: '3' },
    width: { type: 'string', default: '1400' },
    height: { type: 'string', default: '900' },
  },
});
const SHAPE = 'bunny_origin.puz';
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor((values.length - 1) / 2)];
const results = [];
const browser = await openBrowser({ viewport: { width: Number(values.width), height: Number(values.height) } });
try {
  const { page, server } = browser;
  for (let run = 1; run <= Number(values.runs); run += 1) {
    await page.goto(`${server.url}?example=${SHAPE}&parts=${values.parts}&seed=${run}`);
    await showDesignSettings(page);
    await waitForReady(page, SHAPE);
    await page.fill('#design-workers', values.workers);
    const result = await measureLiveDesign(page, { seconds: Number(values.seconds) });
    results.push(result);
    console.log(JSON.stringify({ run, parts: Number(values.parts), workers: Number(values.workers), ...result,
      liveDepths: `${result.liveDepths.length} depths, ${result.liveDepths[0] ?? '-'}..${result.liveDepths.at(-1) ?? '-'}` }));
    await page.click('#design-cancel').catch(() => {});
  }
} finally {
  await browser.close();
}
const summary = {};
for (const field of ['fps', 'blockedMs', 'longestTaskMs', 'longTasks', 'renders', 'seconds']) summary[field] = median(results.map((result) => result[field]));
summary.programsAdded = median(results.map((result) => result.programsAfter - result.programsBefore));
console.log(`median of ${results.length}: ${JSON.stringify(summary)}`);
