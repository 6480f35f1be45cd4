// SPDX-License-Identifier: GPL-3.0-or-later
// A portfolio of voxel designs on threads (all cores): native only, for the CLI. The
// core stays single-threaded (WebAssembly has no threads); this runs independent searches of it.
#pragma once

#include "desia/voxel.h"

namespace desia::cli {

// The default number of searches: one per hardware thread (at least 1).
int defaultDesignJobs();

// Runs `jobs` independent searches of designVoxelPuzzle, with seeds options.seed, options.seed + 1,
// ..., options.seed + jobs - 1, one thread each. The first to find a verified puzzle wins and
// the others are cancelled (their onProgress returns false). The winner's result is returned as
// is: result.seed names its seed, and a single search with that seed (jobs = 1) gives the same
// puzzle, node count and message. Without a winner: the result of the search that got deepest
// (the lowest seed among equals), Cancelled when options.onProgress asked to stop.
// options.onProgress (called from one thread at a time) sees the portfolio's progress: nodes of
// all searches summed, depth and bestDepth of the deepest search. Limits apply to each search.
// jobs = 1 runs designVoxelPuzzle in the calling thread. Rethrows a search's exception
// (BadInput for impossible requests, the same for every seed).
VoxelDesignResult designVoxelPortfolio(const VoxelGrid& shape, const VoxelDesignOptions& options, int jobs);

}  // namespace desia::cli
