// SPDX-License-Identifier: GPL-3.0-or-later
// Plans of mesh assemblies that lie on a lattice (mesh_lattice.h): the complete voxel disassembler's
// plan turned into mesh moves, and every move of it swept on the triangles (paper Section 3.3: a
// move is valid when the moving parts pass every part of their sub-assembly that stays), from where
// the moves before left the parts. A plan that fails a sweep is not used.
#include <cmath>
#include <limits>
#include <sstream>

#include "mesh/mesh_lattice.h"

namespace desia::mesh {
namespace {

constexpr double kOut = std::numeric_limits<double>::infinity();

// The world direction of a voxel move (a unit axis of the grid) and the length of one cell along it.
Vec3 worldDirection(const Vec3& gridDirection, const MeshLattice& lattice, double* pitch) {
  Vec3 d{0, 0, 0};
  for (size_t k = 0; k < 3; ++k) {
    d = plus(d, scaled(lattice.axes[k], gridDirection[k]));
    if (gridDirection[k] != 0) *pitch = lattice.pitch[k];
  }
  return d;
}

TriangleMesh translated(TriangleMesh mesh, const Vec3& offset) {
  for (Vec3& v : mesh.vertices) v = plus(v, offset);
  return mesh;
}

std::string partsText(const MeshAssembly& meshes, const std::vector<int>& parts) {
  std::string text = parts.size() == 1 ? "part" : "parts";
  for (size_t k = 0; k < parts.size(); ++k) {
    text += (k == 0 ? " " : ", ") + std::to_string(meshes.parts[static_cast<size_t>(parts[k])].id);
  }
  return text;
}

// "" when `movers` pass the obstacles along d: to infinity when length is kOut, else at least
// `length` (within the tolerance); else "runs into part ID".
std::string sweepFailure(const MeshAssembly& meshes, const std::vector<PartGeometry>& obstaclesAt,
                         const std::vector<const PartGeometry*>& movers, const std::vector<bool>& obstacles, const Vec3& d,
                         double length) {
  const bool out = std::isinf(length);
  int hit = -1;
  const double travel =
      travelDistance(meshes, obstaclesAt, movers, obstacles, d, out ? kOut : length - meshes.tolerance, &hit);
  if (out ? std::isinf(travel) : travel >= length - meshes.tolerance) return "";
  return "runs into part " + std::to_string(meshes.parts[static_cast<size_t>(hit)].id);
}

// Single-part removals in order, each part along its path from its place, past the parts left.
std::string sweepRemovals(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry, const DisassemblyPlan& plan) {
  std::vector<bool> present(meshes.parts.size(), true);
  size_t left = present.size();
  for (const Removal& removal : plan.removals) {
    if (removal.path.empty()) continue;  // the part that stays
    const size_t part = static_cast<size_t>(removal.part);
    std::vector<bool> obstacles = present;
    obstacles[part] = false;
    Vec3 offset{0, 0, 0};
    for (size_t m = 0; m < removal.path.size(); ++m) {
      const Move& move = removal.path[m];
      const bool out = m + 1 == removal.path.size();
      const PartGeometry moved(translated(meshes.parts[part].mesh, offset));
      const std::string failure = sweepFailure(meshes, geometry, {&moved}, obstacles, move.direction, out ? kOut : move.length);
      if (!failure.empty()) {
        return "part " + std::to_string(meshes.parts[part].id) + ", move " + std::to_string(m + 1) + " along " +
               pointText(move.direction) + ", " + failure;
      }
      offset = plus(offset, scaled(move.direction, move.length));
    }
    present[part] = false;
    --left;
  }
  return left == 1 || !plan.complete ? "" : std::to_string(left) + " parts are left together";
}

// Moves of several parts: each moves its parts past the rest of their sub-assembly, as earlier
// moves left them; a move out makes its parts a sub-assembly of their own.
std::string sweepMoves(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry, const DisassemblyPlan& plan) {
  const size_t n = meshes.parts.size();
  std::vector<PartGeometry> current = geometry;
  std::vector<Vec3> offsets(n, Vec3{0, 0, 0});
  std::vector<int> group(n, 0);
  int groups = 1;
  for (size_t m = 0; m < plan.moves.size(); ++m) {
    const GroupMove& move = plan.moves[m];
    if (move.parts.empty()) return "move " + std::to_string(m + 1) + " moves no part";
    const int from = group[static_cast<size_t>(move.parts.front())];
    std::vector<bool> obstacles(n, false);
    std::vector<const PartGeometry*> movers;
    for (size_t p = 0; p < n; ++p) obstacles[p] = group[p] == from;
    for (int part : move.parts) {
      if (group[static_cast<size_t>(part)] != from) return "move " + std::to_string(m + 1) + " takes parts of two sub-assemblies";
      obstacles[static_cast<size_t>(part)] = false;
      movers.push_back(&current[static_cast<size_t>(part)]);
    }
    const std::string failure =
        sweepFailure(meshes, current, movers, obstacles, move.direction, move.out ? kOut : move.length);
    if (!failure.empty()) {
      return "move " + std::to_string(m + 1) + " (" + partsText(meshes, move.parts) + " along " + pointText(move.direction) +
             ") " + failure;
    }
    for (int part : move.parts) {
      const size_t p = static_cast<size_t>(part);
      if (move.out) {
        group[p] = groups;
      } else {
        offsets[p] = plus(offsets[p], scaled(move.direction, move.length));
        current[p] = PartGeometry(translated(meshes.parts[p].mesh, offsets[p]));
      }
    }
    if (move.out) ++groups;
  }
  std::vector<int> sizes(static_cast<size_t>(groups), 0);
  for (int g : group) ++sizes[static_cast<size_t>(g)];
  for (int size : sizes) {
    if (size > 1 && plan.complete) return std::to_string(size) + " parts are left together";
  }
  return "";
}

}  // namespace

DisassemblyPlan worldPlan(const DisassemblyPlan& voxelPlan, const MeshLattice& lattice) {
  DisassemblyPlan plan = voxelPlan;
  double pitch = 0;
  for (Removal& removal : plan.removals) {
    for (size_t m = 0; m < removal.path.size(); ++m) {
      Move& move = removal.path[m];
      const int steps = move.steps;
      move.direction = worldDirection(move.direction, lattice, &pitch);
      const bool out = m + 1 == removal.path.size();
      move.steps = out ? 1 : 0;
      move.length = out ? 0 : steps * pitch;
    }
  }
  for (GroupMove& move : plan.moves) {
    move.direction = worldDirection(move.direction, lattice, &pitch);
    move.length = move.out ? 0 : move.steps * pitch;
  }
  return plan;
}

std::string sweepPlan(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry, const DisassemblyPlan& plan) {
  if (plan.singlePartPaths) {
    const std::string failure = sweepRemovals(meshes, geometry, plan);
    if (!failure.empty() || plan.movesFollowRemovals) return failure;
  }
  return sweepMoves(meshes, geometry, plan);
}

std::optional<DisassemblyPlan> planOnLattice(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                             std::string* note) {
  const std::optional<MeshLattice> lattice = meshLattice(meshes);
  if (!lattice) return std::nullopt;
  std::ostringstream read;
  read << "read as voxels on a " << lattice->grid.nx() << "x" << lattice->grid.ny() << "x" << lattice->grid.nz()
       << " lattice of " << lattice->pitch[0] << " x " << lattice->pitch[1] << " x " << lattice->pitch[2] << " mm cells";
  const DisassemblyPlan voxelPlan = planVoxelDisassembly(lattice->grid, assemblyFromVoxels(lattice->grid));
  if (!voxelPlan.complete) {
    *note = read.str() + ", the complete voxel disassembler " +
            (voxelPlan.searchLimitReached ? "stopped at its limit (" + voxelPlan.limit + ")" : "finds no plan either");
    return std::nullopt;
  }
  DisassemblyPlan plan = worldPlan(voxelPlan, *lattice);
  const std::string failure = sweepPlan(meshes, geometry, plan);
  if (!failure.empty()) {
    *note = read.str() + ", the voxel plan fails the sweep: " + failure;
    return std::nullopt;
  }
  *note = read.str() + ": planned by the complete voxel disassembler (parts moved together), each move swept";
  return plan;
}

}  // namespace desia::mesh
