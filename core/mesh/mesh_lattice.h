// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh assemblies that are voxel puzzles drawn as meshes: every part an orthogonal polyhedron on
// one common lattice, in the assembly's own frame (any rotation). Read exactly as voxels, they are
// planned by the complete voxel disassembler (moves of several parts, straight and bent), and its
// plan is turned into mesh moves, each swept on the triangles (mesh_plan_sweep.cpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "desia/voxel.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {

struct MeshLattice {
  std::array<Vec3, 3> axes;       // orthonormal, right-handed: the grid's x, y and z in the world
  Vec3 corner{0, 0, 0};           // mm, the world point of the grid's corner (voxel (0,0,0)'s low corner)
  std::array<double, 3> pitch{};  // mm, one cell along each axis
  VoxelGrid grid;                 // label k + 1 = part k (internal index)
};

// The lattice of the parts, or nothing when some face is not square to three common axes, some
// vertex lies off a common lattice by more than the tolerance, or the grid would exceed
// kMostLatticeCells. Exact once the vertices are on the lattice: each part's cells are those of
// positive winding number, counted along z from faces in integer coordinates.
std::optional<MeshLattice> meshLattice(const MeshAssembly& meshes);

// A voxel plan (cells, unit axis moves) as a mesh plan in the world: directions turned by the
// lattice's axes, finite moves of `steps` cells given their `length` in mm, the last move of each
// single-part path out (steps 1, length 0, as the mesh planner writes it).
DisassemblyPlan worldPlan(const DisassemblyPlan& voxelPlan, const MeshLattice& lattice);

// "" when every move of the plan passes the parts it must pass, swept on the triangles from where
// the moves before left every part (travelDistance: a finite move at least its length, a move out
// to infinity), and the plan separates every part; else what went wrong, naming the move.
std::string sweepPlan(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry, const DisassemblyPlan& plan);

// The plan of the parts read as voxels (meshLattice), by planVoxelDisassembly, in the world and
// swept (sweepPlan); nothing when there is no lattice, the voxel plan is incomplete or fails a
// sweep. *note says what was found (the lattice, and why no plan), "" when there is no lattice.
std::optional<DisassemblyPlan> planOnLattice(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                             std::string* note);

}  // namespace desia::mesh
