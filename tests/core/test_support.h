// SPDX-License-Identifier: GPL-3.0-or-later
// Shared fixtures and domain assertions for the core tests.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/plate.h"

namespace desia::testing {

// Path of a file under tests/reference/desia/data (the original authors' data, MIT).
std::string referencePath(const std::string& relative);
std::string readFileText(const std::string& path);
// Path of a file in the repository (examples/, tests/data/).
std::string projectPath(const std::string& relative);
AssemblyDocument loadReference(const std::string& relative);

// Builds a grid from layers of rows, e.g. {{"1 1", "2 2"}, {"1 1", "3 3"}} (z layers of y rows).
VoxelGrid gridFromLayers(const std::vector<std::vector<std::string>>& layers);

// A GoogleTest-safe name from a reference path: "result_puz/Cube_4x4x4_K9.puz" -> "Cube_4x4x4_K9_puz".
std::string testNameFromPath(const std::string& path);

// Part 1 in an S-shaped channel through part 2 (layer z=1, closed above and below): its only way
// out is +x 1, +y 1, then +x.
std::vector<std::vector<std::string>> sChannelLayers();

// Moves one random voxel to a face-adjacent different part; returns false (grid unchanged) if
// that is impossible or the result is not a valid assembly (a part emptied or split).
bool tradeOneVoxel(VoxelGrid& grid, std::mt19937& random);

// Rotations about x, then y, then z by these angles (rad), computed with cos/sin, like a
// modelling tool's export.
std::array<Vec3, 3> rotation(double ax, double ay, double az);

// The plates' vertices turned by `r`, scaled, and rounded to `decimals` (0: not rounded), as a
// CAD tool writes them.
std::vector<Plate> turnedPlates(std::vector<Plate> plates, const std::array<Vec3, 3>& r, double scale = 1,
                                int decimals = 0);

// User-visible ids of internal part indices.
std::vector<int> idsOf(const Assembly& assembly, const std::vector<int>& parts);
std::vector<std::string> labelsOf(const std::vector<Vec3>& directions);

void ExpectInterlocking(const AssemblyDocument& document, const InterlockingResult& result, int keyId,
                        const std::vector<std::string>& keyDirections);

// Re-plays a removal unit step by unit step against the parts still present, independently of
// the planner, then keeps going along the last direction until far outside the grid. Returns an
// empty string when collision-free, otherwise what went wrong.
std::string verifyRemoval(const VoxelGrid& grid, const std::vector<bool>& present, int partId,
                          const std::vector<Move>& path);

// Verifies a complete plan removal by removal (or, for a plan of parts moved together, move by
// move with replayVoxelMoves); returns an empty string when valid.
std::string verifyPlan(const VoxelGrid& grid, const Assembly& assembly, const DisassemblyPlan& plan);

// The voxels of each part (label k at index k - 1), as (x, y, z).
std::vector<std::vector<std::array<int, 3>>> partCells(const VoxelGrid& grid);

// Re-plays moves of sets of parts (parts are grid labels - 1) one unit step at a time, each part
// kept as a set of voxel coordinates, independently of the planner: every moved set must lie in
// one sub-assembly and not be all of it, must not meet a part of its sub-assembly on the way, and
// an `out` move must go on until its parts' box is past the box of the rest, after which they form
// a sub-assembly of their own. With `complete`, every part must end alone. Returns an empty string
// when valid, otherwise what went wrong.
std::string replayVoxelMoves(const VoxelGrid& grid, const std::vector<GroupMove>& moves, bool complete);

// Empty when every directed edge (a, b) of the indexed mesh occurs exactly once and (b, a) exactly
// once: each edge in exactly two triangles, in opposite directions (a closed, consistently oriented
// 2-manifold surface away from its vertices); otherwise the first offending edge.
std::string manifoldProblem(const TriangleMesh& mesh);

// The volume enclosed by an outward-oriented closed surface (divergence theorem: the sum of the
// signed volumes of the tetrahedra origin, a, b, c).
double enclosedVolume(const TriangleMesh& mesh);

// CRC-32 (gzip, ZIP) computed bit by bit: independent of the writers' table.
uint32_t bitwiseCrc32(const std::string& data);

}  // namespace desia::testing
