// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design (issue 11): what the progress line says about a running design besides its counts:
// how hard the request is (voxels per part against what usually succeeds) and, when the pace
// allows one, an estimate of the time left. Pure functions of the progress values: the Design
// panel calls them, node tests can too.

/**
 * Voxels per part below which designs get slow and may fail, from docs/benchmarks.md's measured tables
 * ("Voxel designer" and "Where designs get hard", 2026-11-24, 3 seeds each, 60 s): compact shapes succeed down to
 * 6.25-6.4 voxels per part in a few seconds (4x4x4 N=10: 64/10 in 1.5 s, 5x5x5 N=20: 125/20 in
 * 4.7 s) and fail at 5.8 (4x4x4 N=11: 10 of 11 parts for every seed). So about 6.2 separates easy
 * from hard.
 */
export const HARD_VOXELS_PER_PART = 6.2;
/**
 * Shapes with thin features need more: the bunny succeeds at 8 voxels per part (N=120, 966/120:
 * seeds 1-3 in about 4 s, 9 of seeds 1-14 within 60 s) and fails at 6.9 (N=140: 131-135 of 140);
 * at 8 and above a design usually succeeds.
 */
export const SAFE_VOXELS_PER_PART = 8;

/** One line on the difficulty of splitting `voxels` voxels into `parts` parts. */
export function difficultyText(voxels, parts) {
  if (!(voxels > 0) || !(parts > 0)) return '';
  const perPart = voxels / parts;
  const rounded = perPart >= 10 ? Math.round(perPart) : Math.round(perPart * 10) / 10;
  const head = `~${rounded} voxels per part`;
  if (perPart < HARD_VOXELS_PER_PART) return `${head}: hard, designs below ~${HARD_VOXELS_PER_PART} voxels per part take long and may fail`;
  if (perPart < SAFE_VOXELS_PER_PART) return `${head}: fine for compact shapes; thin ones (the bunny) often fail below ~${SAFE_VOXELS_PER_PART}`;
  return `${head}: usually succeeds`;
}

/**
 * The deepest nodes seen so far of one run, to estimate the time left from the pace at which the
 * best depth grows: `observe(progress)` after every progress value, `estimate(progress)` gives a
 * phrase or '' when no honest estimate can be made (too early, or the search has stopped getting
 * deeper: then it backtracks, which the pace says nothing about).
 */
export function createPaceTracker() {
  let lastGrowthAt = 0;
  let lastDepth = -1;
  return {
    observe(progress) {
      if (progress.bestDepth > lastDepth) {
        lastDepth = progress.bestDepth;
        lastGrowthAt = progress.elapsedSeconds ?? progress.seconds ?? 0;
      }
    },
    estimate(progress, { depthAtEnd = progress.targetParts } = {}) {
      const elapsed = progress.elapsedSeconds ?? progress.seconds ?? 0;
      const done = progress.bestDepth;
      const left = depthAtEnd - done;
      if (done < 2 || elapsed < 0.5 || left <= 0) return '';
      const perDepth = lastGrowthAt / done;
      // Stalled for three times the usual time per part: backtracking near the deepest node.
      if (elapsed - lastGrowthAt > Math.max(1, 3 * perDepth)) return `backtracking at ${done} of ${depthAtEnd} for ${formatSeconds(elapsed - lastGrowthAt)}`;
      return `about ${formatSeconds(perDepth * left)} left at this pace`;
    },
  };
}

function formatSeconds(seconds) {
  if (seconds < 60) return `${Math.max(1, Math.round(seconds))} s`;
  return `${Math.round(seconds / 60)} min`;
}
