// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "desia/analysis.h"
#include "desia/voxel.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::gridFromLayers;

std::vector<std::string> labels(const std::vector<BaseDirection>& directions) {
  std::vector<std::string> result;
  for (const auto& d : directions) result.push_back(d.label());
  return result;
}

Assembly contactsAssembly(int parts, const std::vector<Contact>& contacts) {
  Assembly assembly;
  for (int i = 0; i < parts; ++i) assembly.parts.push_back({i + 1, ""});
  assembly.contacts = contacts;
  return assembly;
}

TEST(BaseDirections, VoxelAssembliesUseTheThreeAxes) {
  const AssemblyDocument document = testing::loadReference("result_puz/Cube_4x4x4_K9.puz");
  EXPECT_EQ(labels(computeBaseDirections(document.assembly)), (std::vector<std::string>{"+x", "+y", "+z"}));
}

TEST(BaseDirections, SlantedContactAddsTheIntersectionsOfGreatCircles) {
  // Normals z and (1,1,0)/sqrt2: great circles z=0 and x+y=0 meet at ±(1,-1,0)/sqrt2 only.
  const double h = std::sqrt(0.5);
  Assembly assembly = contactsAssembly(3, {{0, 1, {0, 0, 1}, 1}, {1, 2, {h, h, 0}, 1}});
  const auto directions = computeBaseDirections(assembly);
  ASSERT_EQ(directions.size(), 1u);
  EXPECT_NEAR(directions[0].vector[0], h, 1e-12);
  EXPECT_NEAR(directions[0].vector[1], -h, 1e-12);
  EXPECT_NEAR(directions[0].vector[2], 0, 1e-12);
  // Adding an x normal adds the vertices x×z = y and x×(1,1,0) = z.
  assembly.contacts.push_back({0, 2, {1, 0, 0}, 1});
  EXPECT_EQ(labels(computeBaseDirections(assembly)), (std::vector<std::string>{"+y", "+z", "(0.7071,-0.7071,0)"}));
}

TEST(BaseDirections, ParallelNormalsGiveAPerpendicularDirection) {
  // All normals on one slanted line: a single great circle with no vertex. The direction chosen
  // lies on it (orthogonal to the normal), where every part is free.
  const double h = std::sqrt(0.5);
  Assembly assembly = contactsAssembly(2, {{0, 1, {h, h, 0}, 1}, {1, 0, {-h, -h, 0}, 1}});
  const auto directions = computeBaseDirections(assembly);
  ASSERT_EQ(directions.size(), 1u);
  EXPECT_NEAR(directions[0].vector[0] * h + directions[0].vector[1] * h, 0.0, 1e-12);
  EXPECT_EQ(buildBlockingGraph(assembly, directions[0]).graph.edgeCount(), 0);
}

TEST(BaseDirections, AxisAlignedAssembliesAlwaysGetTheThreeAxes) {
  // Contacts along x only (a row of voxels): +y and +z lie on the arrangement's circle, +x does not,
  // but voxel puzzles keep all three graphs.
  const Assembly assembly = assemblyFromVoxels(gridFromLayers({{"1 2 3"}}));
  EXPECT_EQ(labels(computeBaseDirections(assembly)), (std::vector<std::string>{"+x", "+y", "+z"}));
}

TEST(BlockingGraph, EdgeMeansBlockedByAlongDirection) {
  // Part 1 at x=0, part 2 at x=1: moving 1 along +x pushes into 2, so 1 -> 2 in G(+x).
  const VoxelGrid grid = gridFromLayers({{"1 2 3"}});
  const Assembly assembly = assemblyFromVoxels(grid);
  const auto graphs = buildBaseBlockingGraphs(assembly);
  ASSERT_EQ(graphs[0].direction.label(), "+x");
  EXPECT_TRUE(graphs[0].graph.hasEdge(0, 1));
  EXPECT_TRUE(graphs[0].graph.hasEdge(1, 2));
  EXPECT_FALSE(graphs[0].graph.hasEdge(1, 0));
  EXPECT_EQ(graphs[1].graph.edgeCount(), 0);  // nothing blocks along y
}

TEST(VoxelContacts, OneContactPerPairAndAxisWithFaceArea) {
  const VoxelGrid grid = gridFromLayers({{"1 2", "1 2"}});
  const Assembly assembly = assemblyFromVoxels(grid);
  ASSERT_EQ(assembly.contacts.size(), 1u);
  EXPECT_EQ(assembly.contacts[0].a, 0);
  EXPECT_EQ(assembly.contacts[0].b, 1);
  EXPECT_EQ(assembly.contacts[0].normal, (Vec3{1, 0, 0}));
  EXPECT_EQ(assembly.contacts[0].area, 2.0);
}

}  // namespace
}  // namespace desia
