// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design (issue 11): what the progress line says about a running design besides its counts:
// how hard the request is (voxels per part against what usually succeeds) and, when the pace
// allows one, an estimate of the time left. Pure functions of the progress values: the Design
// panel calls them, node tests can too.

/**
 * Voxels per part below which designs get slow and may fail, from the README's measured tables
 * ("Measured (designer)", 2026-11-24, 3 seeds each): compact shapes succeed at 7.1-7.8 voxels per
 * part in well under a second (4x4x4 N=9: 64/9, 6x6x6 N=30: 216/30, 5x5x5 N=16: 125/16), and at
 * 6.25-6.4 only since issue 10's enumerated last splits, in 13 to 39 s (4x4x4 N=10: 6.4, 5x5x5
 * N=20: 6.25); below that nothing was measured. So about 7 separates easy from hard.
 */
export const HARD_VOXELS_PER_PART = 7;
/**
 * Shapes with thin features need more: the bunny succeeds at 12 voxels per part (N=80, 966/80)
 * and fails at 9.7 and 8.1 (N=100, N=120); above about 10 a design usually succeeds.
 */
export const SAFE_VOXELS_PER_PART = 10;

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
