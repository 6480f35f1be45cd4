// SPDX-License-Identifier: GPL-3.0-or-later
//
// How smooth the page stays while a design draws its deepest node (issue 28, item 8): frames the
// page managed (requestAnimationFrame callbacks), long tasks (PerformanceObserver 'longtask':
// main-thread tasks over 50 ms) and the shader programs three.js holds, over a window of a
// running design. Used by tests/browser/live.test.mjs (lenient bounds) and by
// tests/benchmarks/live_design_bench.mjs (the measurement in docs/benchmarks.md). Not a test file itself.

/**
 * Clicks Design and measures for `seconds` (or until the design ends, if sooner): resolves with
 * { seconds, frames, fps, longTasks, longestTaskMs, blockedMs, programsBefore, programsAfter,
 * renders (frames the 3D view drew), liveDepths, maxLiveCalls (the most draw calls of a frame that
 * showed a live picture), outcome }. The Design form must be filled in already.
 */
export async function measureLiveDesign(page, { seconds = 5 } = {}) {
  await page.evaluate(() => {
    const state = { frames: 0, longTasks: [], programs: [], depths: new Set(), running: true };
    window.__liveFrames = state;
    state.observer = new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) state.longTasks.push({ start: entry.startTime, duration: entry.duration });
    });
    state.observer.observe({ type: 'longtask' });
    const stats = window.__desiaView.renderStats();
    state.programsBefore = stats.programs;
    state.rendersBefore = stats.framesRendered;
    // Draw calls of the view's frames that showed a live picture (the frame after the first
    // live depth appeared; the picture before it is the input's).
    state.maxLiveCalls = 0;
    const frame = () => {
      if (!state.running) return;
      state.frames += 1;
      const depth = document.querySelector('#design-progress-box').dataset.liveParts;
      if (depth) state.depths.add(Number(depth));
      const now = window.__desiaView.renderStats();
      if (depth && document.body.dataset.design === 'running') {
        state.rendersAtLive ??= now.framesRendered;
        if (now.framesRendered > state.rendersAtLive) state.maxLiveCalls = Math.max(state.maxLiveCalls, now.calls);
      }
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  });
  await page.click('#design-button');
  const started = Date.now();
  // A design that ends early ends the window: what the page did while it ran is what counts.
  await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: seconds * 1000 }).catch(() => {});
  const elapsed = (Date.now() - started) / 1000;
  return page.evaluate((windowSeconds) => {
    const state = window.__liveFrames;
    state.running = false;
    state.observer.disconnect();
    const stats = window.__desiaView.renderStats();
    const durations = state.longTasks.map((task) => task.duration);
    return {
      seconds: windowSeconds,
      frames: state.frames,
      fps: Math.round((state.frames / windowSeconds) * 10) / 10,
      longTasks: durations.length,
      longestTaskMs: Math.round(Math.max(0, ...durations)),
      blockedMs: Math.round(durations.reduce((sum, duration) => sum + duration, 0)),
      programsBefore: state.programsBefore,
      programsAfter: stats.programs,
      renders: stats.framesRendered - state.rendersBefore,
      liveDepths: [...state.depths].sort((a, b) => a - b),
      maxLiveCalls: state.maxLiveCalls,
      outcome: document.body.dataset.design,
    };
  }, elapsed);
}
