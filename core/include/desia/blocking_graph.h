// SPDX-License-Identifier: GPL-3.0-or-later
// Directional blocking graphs (paper Section 3.1). G(d) has an edge i->j when part j blocks the
// translation of part i along d. Base directions are the directions where the non-directional
// blocking graph changes; one base DBG per direction on a half sphere suffices because
// G(-d) is G(d) reversed.
#pragma once

#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/directed_graph.h"

namespace desia {

// Label of a direction: "+x" / "-y" for axes, a rounded vector otherwise.
std::string directionLabel(const Vec3& direction);

struct BaseDirection {
  Vec3 vector{0, 0, 0};   // unit length, canonical sign (first non-zero component positive)
  // "+x", "+y", "+z" for axes, otherwise "(0.707,0.707,0)"; made when asked for, since an
  // assembly can have hundreds of thousands of base directions and few are ever named.
  std::string label() const { return directionLabel(vector); }
};

// The vertices of the arrangement of great circles {d : d·n = 0} on the unit sphere, one of each
// antipodal pair (the 3D analogue of the points of Fig. 3e). For axis-aligned contacts these are
// exactly +x, +y, +z. Degenerate arrangements (all normals parallel, or no contacts) still get
// directions that span the free motions, so a free part is never missed.
std::vector<BaseDirection> computeBaseDirections(const Assembly& assembly);

struct DirectionalBlockingGraph {
  BaseDirection direction;
  DirectedGraph graph;  // nodes are part indices
};

// Infinitesimal blocking: i is blocked by j along d iff some contact normal n from i to j has
// d·n > 0 (moving i along d would penetrate j).
DirectionalBlockingGraph buildBlockingGraph(const Assembly& assembly, const BaseDirection& direction);

// The same graphs for many directions of one assembly. Across many directions, contacts are
// grouped by pair of parts once, and a pair is no longer examined once it blocks both ways
// (hundreds of contacts between two parts then cost a few dot products per direction); across a
// few (voxel assemblies: three) the grouping would cost more than it saves, and is skipped.
class BlockingGraphBuilder {
 public:
  // Keeps a reference to `assembly`, which must outlive the builder.
  BlockingGraphBuilder(const Assembly& assembly, size_t directionCount);
  DirectionalBlockingGraph build(const BaseDirection& direction) const;
  // Rebuilds `graph` in place (its node count must be the assembly's), reusing its memory.
  void buildInto(const BaseDirection& direction, DirectionalBlockingGraph* graph) const;

 private:
  struct PairContacts {
    int a = 0, b = 0;           // a < b
    std::vector<Vec3> normals;  // oriented from a towards b, distinct
  };
  const Assembly& assembly_;
  bool grouped_ = false;
  std::vector<PairContacts> pairs_;
};

std::vector<DirectionalBlockingGraph> buildBaseBlockingGraphs(const Assembly& assembly);

}  // namespace desia
