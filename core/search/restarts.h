// SPDX-License-Identifier: GPL-3.0-or-later
// Restarts of the seeded depth-first construction search (search/construction_search.h): each search tree
// gets a budget from the Luby sequence, in work the search counts (never time, so the same seed
// gives the same result), and a random state derived from the user's seed.
#pragma once

#include <cstdint>

namespace desia {

// The Luby sequence 1, 1, 2, 1, 1, 2, 4, 1, ... at 0-based index `index` (Luby, Sinclair and
// Zuckerman 1993: within a constant factor of the best fixed restart budget for any runtime
// distribution).
inline int64_t lubyTerm(int64_t index) {
  int64_t size = 1;
  int seq = 0;
  while (size < index + 1) {
    ++seq;
    size = 2 * size + 1;
  }
  while (size - 1 != index) {
    size = (size - 1) >> 1;
    --seq;
    index %= size;
  }
  return int64_t(1) << seq;
}

// SplitMix64's output mix (Steele, Lea and Flood 2014): nearby inputs give unrelated outputs, so
// the random states of restarts differ from every other seed's.
inline uint64_t splitMix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The random state of restart `attempt` for the user's seed, the one seeding of every designer:
// attempt 0 is `firstState`, the kind's own state for the seed; later attempts mix the attempt
// (and the kind's `salt`) in, so their orders differ from every other seed's. Each kind keeps the
// first state and salt its results were made with (voxel puzzles: the seed itself and
// kVoxelRestartSalt; plates and frames: seed * golden ratio + 1 and + 7, no salt).
inline uint64_t restartState(uint64_t seed, int64_t attempt, uint64_t firstState, uint64_t salt = 0) {
  if (attempt == 0) return firstState;
  return splitMix64(seed + 0x9E3779B97F4A7C15ull * static_cast<uint64_t>(attempt + 1) + salt);
}

constexpr uint64_t kVoxelRestartSalt = 0x5851F42D4C957F2Dull;

}  // namespace desia
