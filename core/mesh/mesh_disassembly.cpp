// SPDX-License-Identifier: GPL-3.0-or-later
// Disassembly of a mesh assembly by translations (paper Section 3.3): in each sub-assembly, a single
// part that its contacts let move along some direction and that the sweep lets leave, straight or
// by a bent path of up to three moves; where none can, a group of parts: all that one part drags along d in the blocking graph of the sub-assembly
// (G(d): i -> j when j blocks i), swept together past the others. A group moved out becomes a
// sub-assembly of its own; the plan is done when every sub-assembly is one part.
#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <string>

#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/tolerances.h"
#include "mesh/group_search_entry.h"
#include "mesh/mesh_geometry.h"
#include "mesh/mesh_lattice.h"

namespace desia::mesh {
namespace {

// A part with more vertex levels than this along a slide (a curved or finely meshed part) stops
// only where the slide ends: trying every level would cost a sweep each.
constexpr size_t kMaxLevels = 64;

// Bent paths: at most this many translations (the last one out), and at most this many sweeps
// tried for one slide (work, not time: the same plan everywhere).
constexpr size_t kMostPathMoves = 3;
constexpr int kMostBentSweeps = 600;
// Bent-path sweeps for the whole plan: a large assembly stuck with many parts that slide a little
// would otherwise try every slide of every part after every removal. Past it the plan stops as
// "not proven" (searchLimitReached), like the voxel planner at its work limit.
constexpr int kBentSweepBudget = 20000;

// A point on a bent path: the part's offset from its place and the moves that took it there.
struct Waypoint {
  Vec3 offset;
  std::vector<Move> path;
};

struct Slide {
  int part;
  Vec3 d;
  double travel;  // mm it can move along d
};

// Can `part` move along d by its contacts? As isPartFreeAlong, but a motion within
// tolerance::kDrawnDirectionRad of a contact's plane slides along it: contact normals of drawn
// meshes, and the base directions crossed from them, are off by that much (the sweep that follows
// is what decides).
bool freeAlong(const Assembly& local, int part, const Vec3& d) {
  for (const Contact& contact : local.contacts) {
    if (contact.a == part && dot(d, contact.normal) > tolerance::kDrawnDirectionRad) return false;
    if (contact.b == part && dot(d, contact.normal) < -tolerance::kDrawnDirectionRad) return false;
  }
  return true;
}

class Planner {
 public:
  Planner(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry)
      : meshes_(meshes), geometry_(geometry), contactsOfPart_(meshes.parts.size()) {
    const auto& contacts = meshes.assembly.contacts;
    for (size_t c = 0; c < contacts.size(); ++c) {
      contactsOfPart_[static_cast<size_t>(contacts[c].a)].push_back(static_cast<int>(c));
      contactsOfPart_[static_cast<size_t>(contacts[c].b)].push_back(static_cast<int>(c));
    }
  }

  DisassemblyPlan plan() {
    const int n = meshes_.assembly.partCount();
    std::vector<int> all(static_cast<size_t>(n));
    for (int p = 0; p < n; ++p) all[static_cast<size_t>(p)] = p;
    std::vector<std::vector<int>> pending{all};
    DisassemblyPlan plan;
    bool grouped = false;
    while (!pending.empty()) {
      std::vector<int> together = std::move(pending.back());
      pending.pop_back();
      while (together.size() > 1) {
        Removal removal;
        GroupMove move;
        if (singleRemoval(together, &removal)) {
          plan.removals.push_back(removal);
          for (const Move& step : removal.path) plan.moves.push_back({{removal.part}, step.direction, 0, step.length == 0});
          move.parts = {removal.part};
        } else if (groupRemoval(together, &move)) {
          grouped = true;
          pending.push_back(move.parts);
          plan.moves.push_back(move);
        } else {
          break;
        }
        std::vector<int> rest;
        std::set_difference(together.begin(), together.end(), move.parts.begin(), move.parts.end(),
                            std::back_inserter(rest));
        together = std::move(rest);
      }
      if (together.size() > 1) {
        plan.unseparated.push_back(together);
        plan.stuck.insert(plan.stuck.end(), together.begin(), together.end());
      } else {
        plan.removals.push_back({together[0], {}});
      }
    }
    std::sort(plan.stuck.begin(), plan.stuck.end());
    plan.complete = plan.stuck.empty();
    if (!plan.complete && bentBudgetSpent_) {
      plan.searchLimitReached = true;
      plan.limit = std::to_string(kBentSweepBudget) + " sweeps of bent paths";
    }
    if (grouped) {
      plan.singlePartPaths = false;
      plan.movesFollowRemovals = false;
      for (Removal& removal : plan.removals) removal.path.clear();
    } else {
      plan.moves.clear();  // the removals' paths say it all
      if (!plan.complete) plan.unseparated.clear();
    }
    return plan;
  }

 private:
  // Contacts among the parts of `together` (all of them, or those of one part).
  Assembly localContacts(const std::vector<int>& together, int onlyPart) const {
    std::vector<bool> inside(meshes_.parts.size(), false);
    for (int p : together) inside[static_cast<size_t>(p)] = true;
    Assembly local;
    // No parts: base directions and freedom read the contacts alone (a copy per try was quadratic).
    const auto& contacts = meshes_.assembly.contacts;
    auto keep = [&](int c) {
      const Contact& contact = contacts[static_cast<size_t>(c)];
      if (inside[static_cast<size_t>(contact.a)] && inside[static_cast<size_t>(contact.b)]) local.contacts.push_back(contact);
    };
    if (onlyPart >= 0) {
      for (int c : contactsOfPart_[static_cast<size_t>(onlyPart)]) keep(c);
    } else {
      for (size_t c = 0; c < contacts.size(); ++c) keep(static_cast<int>(c));
    }
    return local;
  }

  std::vector<bool> presentMask(const std::vector<int>& together) const {
    std::vector<bool> present(meshes_.parts.size(), false);
    for (int p : together) present[static_cast<size_t>(p)] = true;
    return present;
  }

  // The first part, in index order, that its contacts let move along a base direction of its own
  // contacts (either sign) and that the sweep lets leave along it; else the first that leaves by a
  // bent path (bentRemoval).
  bool singleRemoval(const std::vector<int>& together, Removal* removal) const {
    const std::vector<bool> present = presentMask(together);
    std::vector<Slide> slides;
    for (int part : together) {
      const Assembly local = localContacts(together, part);
      std::vector<bool> obstacles = present;
      obstacles[static_cast<size_t>(part)] = false;
      for (const BaseDirection& base : computeBaseDirections(local)) {
        for (const Vec3& d : {base.vector, negated(base.vector)}) {
          if (!freeAlong(local, part, d)) continue;
          const double travel = travelDistance(meshes_, geometry_, {&geometry_[static_cast<size_t>(part)]}, obstacles, d,
                                               meshes_.tolerance, nullptr);
          if (std::isinf(travel)) {
            *removal = Removal{part, {Move{d, 1}}};
            return true;
          }
          if (travel > meshes_.tolerance) slides.push_back({part, d, travel});
        }
      }
    }
    const std::vector<BaseDirection> bases = computeBaseDirections(localContacts(together, -1));
    for (const Slide& slide : slides) {
      if (bentRemoval(slide, bases, present, removal)) return true;
    }
    return false;
  }

  // A part its contacts let move along d1 but that something stops after `travel`: a bent path of
  // at most kMostPathMoves translations (paper Section 3.3), breadth-first so that the fewest moves
  // win. From each waypoint, every base direction (either sign) but the last move's line: out, if
  // the sweep lets the part leave; else, while moves are left, to each distance where its vertex
  // levels meet another part's (or where it touches). At most kMostBentSweeps sweeps per slide.
  bool bentRemoval(const Slide& slide, const std::vector<BaseDirection>& bases, const std::vector<bool>& present,
                   Removal* removal) const {
    std::vector<bool> obstacles = present;
    obstacles[static_cast<size_t>(slide.part)] = false;
    const MeshPart& part = meshes_.parts[static_cast<size_t>(slide.part)];
    std::deque<Waypoint> queue;
    std::vector<Vec3> seen;
    const auto visit = [&](const Waypoint& from, const Vec3& d, double distance) {
      const Vec3 offset = plus(from.offset, scaled(d, distance));
      for (const Vec3& other : seen) {
        if (norm(minus(other, offset)) <= meshes_.tolerance) return;
      }
      seen.push_back(offset);
      Waypoint next{offset, from.path};
      next.path.push_back(Move{d, 0, distance});
      queue.push_back(std::move(next));
    };
    const Waypoint start{{0, 0, 0}, {}};
    for (double distance : stopDistances(slide.part, start.offset, slide.d, slide.travel, present)) {
      visit(start, slide.d, distance);
    }
    int sweeps = 0;
    while (!queue.empty() && sweeps < kMostBentSweeps) {
      if (bentSweepsLeft_ <= 0) {
        bentBudgetSpent_ = true;
        return false;
      }
      const Waypoint at = std::move(queue.front());
      queue.pop_front();
      TriangleMesh moved = part.mesh;
      for (Vec3& v : moved.vertices) v = plus(v, at.offset);
      const PartGeometry movedGeometry(moved);
      const bool lastMove = at.path.size() + 1 >= kMostPathMoves;
      for (const BaseDirection& base : bases) {
        for (const Vec3& d : {base.vector, negated(base.vector)}) {
          if (std::abs(dot(d, at.path.back().direction)) >= 1 - tolerance::kDirection) continue;
          ++sweeps;
          --bentSweepsLeft_;
          const double travel = travelDistance(meshes_, geometry_, {&movedGeometry}, obstacles, d,
                                               lastMove ? meshes_.tolerance : 0, nullptr);
          if (std::isinf(travel)) {
            *removal = Removal{slide.part, at.path};
            removal->path.push_back(Move{d, 1});
            return true;
          }
          if (lastMove || travel <= meshes_.tolerance) continue;
          for (double distance : stopDistances(slide.part, at.offset, d, travel, present)) visit(at, d, distance);
        }
      }
    }
    return false;
  }

  // Where the part, moved by `offset`, may stop on its way along d: each distance (below the
  // travel) at which one of its vertex levels along d meets a vertex level of a part present, and
  // the travel itself.
  std::vector<double> stopDistances(int mover, const Vec3& offset, const Vec3& d, double travel,
                                    const std::vector<bool>& present) const {
    const auto levels = [&](size_t part, double shift) {
      std::vector<double> values;
      for (const Vec3& v : meshes_.parts[part].mesh.vertices) values.push_back(dot(v, d) + shift);
      std::sort(values.begin(), values.end());
      std::vector<double> distinct;
      for (double value : values) {
        if (distinct.empty() || value - distinct.back() > meshes_.tolerance) distinct.push_back(value);
      }
      return distinct;
    };
    const std::vector<double> own = levels(static_cast<size_t>(mover), dot(offset, d));
    std::vector<double> distances{travel};
    if (own.size() > kMaxLevels) return distances;
    for (size_t other = 0; other < present.size(); ++other) {
      if (!present[other] || static_cast<int>(other) == mover) continue;
      const std::vector<double> theirs = levels(other, 0);
      if (theirs.size() > kMaxLevels) continue;
      for (double mine : own) {
        for (double level : theirs) {
          const double distance = level - mine;
          if (distance > meshes_.tolerance && distance < travel - meshes_.tolerance) distances.push_back(distance);
        }
      }
    }
    std::sort(distances.begin(), distances.end());
    std::vector<double> distinct;
    for (double distance : distances) {
      if (distinct.empty() || distance - distinct.back() > meshes_.tolerance) distinct.push_back(distance);
    }
    return distinct;
  }

  // The parts `part` drags along d: those reachable from it in G(d) among the parts present.
  std::vector<int> dragged(const std::vector<bool>& present, int part, const Vec3& d) const {
    std::vector<bool> in(meshes_.parts.size(), false);
    std::vector<int> stack{part}, group;
    in[static_cast<size_t>(part)] = true;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      group.push_back(i);
      for (int c : contactsOfPart_[static_cast<size_t>(i)]) {
        const Contact& contact = meshes_.assembly.contacts[static_cast<size_t>(c)];
        const double along = dot(d, contact.normal);
        int j = -1;
        if (contact.a == i && along > tolerance::kDrawnDirectionRad) j = contact.b;
        if (contact.b == i && along < -tolerance::kDrawnDirectionRad) j = contact.a;
        if (j < 0 || !present[static_cast<size_t>(j)] || in[static_cast<size_t>(j)]) continue;
        in[static_cast<size_t>(j)] = true;
        stack.push_back(j);
      }
    }
    std::sort(group.begin(), group.end());
    return group;
  }

  bool groupRemoval(const std::vector<int>& together, GroupMove* move) const {
    const std::vector<bool> present = presentMask(together);
    const Assembly local = localContacts(together, -1);
    std::set<std::vector<int>> tried;
    for (const BaseDirection& base : computeBaseDirections(local)) {
      for (const Vec3& d : {base.vector, negated(base.vector)}) {
        tried.clear();
        for (int part : together) {
          const std::vector<int> group = dragged(present, part, d);
          if (group.size() == together.size() || !tried.insert(group).second) continue;
          if (!sweepObstacle(meshes_, geometry_, group, present, d).empty()) continue;
          *move = GroupMove{group, d, 0, true};
          return true;
        }
      }
    }
    return false;
  }

  const MeshAssembly& meshes_;
  const std::vector<PartGeometry>& geometry_;
  std::vector<std::vector<int>> contactsOfPart_;
  mutable int bentSweepsLeft_ = kBentSweepBudget;
  mutable bool bentBudgetSpent_ = false;
};

}  // namespace

DisassemblyPlan planWithGeometry(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                                 std::string* note) {
  DisassemblyPlan plan = Planner(meshes, geometry).plan();
  if (plan.complete) return plan;
  std::string latticeNote;
  std::optional<DisassemblyPlan> onLattice = planOnLattice(meshes, geometry, &latticeNote);
  if (note) *note = latticeNote;
  if (onLattice) return *onLattice;
  if (!latticeNote.empty()) return plan;  // on a lattice, the voxel disassembler's search was complete
  // Off any lattice: the search for finite moves of several parts (mesh_group_search.cpp).
  std::string searchNote, limit;
  std::optional<DisassemblyPlan> byGroups = planOffLatticeGroupMoves(meshes, geometry, &searchNote, &limit);
  if (note) *note = searchNote;
  if (byGroups) return *byGroups;
  if (!limit.empty()) {
    plan.searchLimitReached = true;
    plan.limit = limit;
  }
  return plan;
}

}  // namespace desia::mesh

namespace desia {

DisassemblyPlan planMeshDisassembly(const MeshAssembly& meshes) {
  return mesh::planWithGeometry(meshes, mesh::geometryOf(meshes));
}

}  // namespace desia
