// SPDX-License-Identifier: GPL-3.0-or-later
// Graph design for P_i and R_i (paper Section 4.3, Fig. 7): each case, once realized in voxels,
// puts its cycle into the DBG of A_i.
#include <gtest/gtest.h>

#include <map>

#include "desia/analysis.h"
#include "desia/voxel.h"
#include "test_support.h"
#include "voxel/graph_design.h"

namespace desia {
namespace {

using design::AxisDesign;

const char* designName(AxisDesign design) {
  switch (design) {
    case AxisDesign::TwoInternal: return "K=2";
    case AxisDesign::OneInternalPartToRemainder: return "K=1 (P->R)";
    case AxisDesign::OneInternalRemainderToPart: return "K=1 (R->P)";
    case AxisDesign::NoInternal: return "K=0";
  }
  return "?";
}

// Does G contain a cycle P -> ... -> P of the design's shape? `part` and `remainder` are node
// indices in A_i; earlier parts are 0..part-1; `reaches` is over earlier part labels (1-based).
bool hasDesignCycle(AxisDesign design, const DirectedGraph& g, int part, int remainder,
                    const design::PartReachability& reaches) {
  auto edge = [&](int from, int to) { return g.hasEdge(from, to); };
  auto path = [&](int from, int to) { return reaches(from + 1, to + 1); };  // P_out ~> P_in
  for (int out = 0; out < part; ++out) {
    for (int in = 0; in < part; ++in) {
      if (!path(out, in)) continue;
      switch (design) {
        case AxisDesign::OneInternalPartToRemainder:
          if (edge(part, remainder) && edge(remainder, out) && edge(in, part)) return true;
          break;
        case AxisDesign::OneInternalRemainderToPart:
          if (edge(remainder, part) && edge(part, out) && edge(in, remainder)) return true;
          break;
        case AxisDesign::NoInternal:
          if (!edge(part, out) || !edge(in, remainder)) break;
          for (int out2 = 0; out2 < part; ++out2) {
            for (int in2 = 0; in2 < part; ++in2) {
              if (path(out2, in2) && edge(remainder, out2) && edge(in2, part)) return true;
            }
          }
          break;
        case AxisDesign::TwoInternal:
          break;
      }
    }
  }
  return design == AxisDesign::TwoInternal && edge(part, remainder) && edge(remainder, part);
}

// A real intermediate assembly: the 4x4x4 cube after three placed parts (labels 1..3, R = 4).
VoxelGrid cubeAfterThreeParts(const VoxelDesignOptions& options) {
  VoxelDesignSession session(testing::loadReference("input_puz/Cube_4x4x4_origin.puz").voxels, options);
  for (int k = 0; k < 3; ++k) {
    if (!session.generateNextPart()) throw std::runtime_error("fixture: the session stopped early");
  }
  return session.current();
}

VoxelDesignOptions eightPartOptions() {
  VoxelDesignOptions options;
  options.parts = 8;
  options.seed = 3;
  return options;
}

TEST(GraphDesign, EveryCaseRealizedPutsItsCycleIntoTheBlockingGraph) {
  const VoxelDesignOptions options = eightPartOptions();
  const VoxelGrid grid = cubeAfterThreeParts(options);
  const int remainder = 4;
  ASSERT_EQ(grid.maxLabel(), remainder);
  const Assembly before = assemblyFromVoxels(grid);
  const auto graphs = buildBaseBlockingGraphs(before);
  design::DesignContext context{options, {}, {}, 64, std::mt19937_64(1)};
  const std::vector<double> access = design::accessibility(grid, remainder);

  std::map<AxisDesign, int> realized;
  std::mt19937_64 random(9);
  for (int axis = 0; axis < 3; ++axis) {
    const design::AxisInfo info = design::describeAxis(grid, remainder, axis, graphs[axis].graph, false);
    const Int3 e = design::axisStep(axis);
    // Leave along another axis so that every design is allowed on this one.
    const Int3 removal = design::axisStep((axis + 1) % 3);
    ASSERT_EQ(design::allowedDesigns(axis, removal).size(), 4u);
    for (AxisDesign design : design::allowedDesigns(axis, removal)) {
      for (int64_t seed = 0; seed < grid.voxelCount(); ++seed) {
        if (grid.labelAt(seed) != remainder) continue;
        design::PartBuilder builder(grid, remainder, context, access);
        if (!builder.forcePart(seed) ||
            !design::realizeAxis(design, axis, info, grid, grid.coordinates(seed), random, builder) || !builder.connect() ||
            !builder.clearPathAlong(removal)) {
          continue;
        }
        VoxelGrid next = grid;
        design::applyCandidate(next, remainder, design::Candidate{builder.sortedPartVoxels(), 0});
        if (!design::isFaceConnected(next, remainder + 1)) continue;
        const Assembly after = assemblyFromVoxels(next);
        const DirectionalBlockingGraph g = buildBlockingGraph(after, BaseDirection{{double(e.x), double(e.y), double(e.z)}});
        EXPECT_TRUE(hasDesignCycle(design, g.graph, remainder - 1, remainder, info.reaches))
            << designName(design) << " on axis " << axis << " from seed voxel " << seed;
        ++realized[design];
      }
    }
  }
  // Each of the four cases of Fig. 7 was realized somewhere in this assembly.
  for (AxisDesign design : {AxisDesign::TwoInternal, AxisDesign::OneInternalPartToRemainder,
                            AxisDesign::OneInternalRemainderToPart, AxisDesign::NoInternal}) {
    EXPECT_GT(realized[design], 0) << designName(design);
  }
}

TEST(GraphDesign, TheRemovalDirectionForbidsTheBlockingInternalEdge) {
  // Leaving along +e: no P -> R edge may be built in G(+e) (R in front of P), so K = 2 and
  // K = 1 (P -> R) are out; along -e the mirror.
  EXPECT_EQ(design::allowedDesigns(1, {0, 1, 0}),
            (std::vector<AxisDesign>{AxisDesign::NoInternal, AxisDesign::OneInternalRemainderToPart}));
  EXPECT_EQ(design::allowedDesigns(1, {0, -1, 0}),
            (std::vector<AxisDesign>{AxisDesign::NoInternal, AxisDesign::OneInternalPartToRemainder}));
}

TEST(GraphDesign, RecursiveModeClosesCyclesThroughThePreviousPartOnly) {
  const VoxelGrid grid = cubeAfterThreeParts(eightPartOptions());
  const auto graphs = buildBaseBlockingGraphs(assemblyFromVoxels(grid));
  for (int axis = 0; axis < 3; ++axis) {
    const design::AxisInfo info = design::describeAxis(grid, 4, axis, graphs[axis].graph, true);
    for (const auto& contact : info.remainderBlockedBy) EXPECT_EQ(contact.part, 3);
    for (const auto& contact : info.blockingPart) EXPECT_EQ(contact.part, 3);
  }
}

TEST(GraphDesign, ReachabilityRowsAreTheClosureWithoutTheRemainder) {
  // Rows searched on demand (PartReachability) against the transitive closure of G(+e) with R
  // removed, computed by repeated squaring over all pairs.
  const VoxelGrid grid = cubeAfterThreeParts(eightPartOptions());
  const int remainder = 4;
  const auto graphs = buildBaseBlockingGraphs(assemblyFromVoxels(grid));
  for (int axis = 0; axis < 3; ++axis) {
    const design::PartReachability reaches(graphs[axis].graph, remainder);
    std::vector<std::vector<bool>> closure(remainder, std::vector<bool>(remainder, false));
    for (int a = 1; a < remainder; ++a) {
      closure[a][a] = true;
      for (int b = 1; b < remainder; ++b) closure[a][b] = closure[a][b] || graphs[axis].graph.hasEdge(a - 1, b - 1);
    }
    for (int k = 1; k < remainder; ++k) {
      for (int a = 1; a < remainder; ++a) {
        for (int b = 1; b < remainder; ++b) closure[a][b] = closure[a][b] || (closure[a][k] && closure[k][b]);
      }
    }
    for (int a = 1; a < remainder; ++a) {
      for (int b = 1; b < remainder; ++b) EXPECT_EQ(reaches(a, b), closure[a][b]) << axis << " " << a << " " << b;
    }
  }
}

TEST(Backtracking, HardDesignsSucceedAfterBacktracking) {
  // The hollow cube needs the search to back up to siblings and ancestors (Algorithm 1 lines 18-29).
  const VoxelGrid hollow = testing::loadReference("input_puz/Cube_hollow_4x4x4_origin.puz").voxels;
  VoxelDesignOptions options;
  options.parts = 7;
  options.seed = 1;
  options.limits.timeLimitSeconds = 120;
  const VoxelDesignResult result = designVoxelPuzzle(hollow, options);
  ASSERT_EQ(result.status, DesignStatus::Success) << result.message;
  EXPECT_GT(result.progress.nodes, options.parts - 1);  // more nodes than the path: it backtracked
  EXPECT_EQ(result.message.find(" 0 backtracks"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace desia
