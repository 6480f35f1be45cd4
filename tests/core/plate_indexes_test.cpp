// SPDX-License-Identifier: GPL-3.0-or-later
// The indexes that keep plate designs of thousands of plates from quadratic work (issue 24) give
// what comparing every pair gives: the groups of parallel normals (a grid of cells), the pairs of
// nearly square directions (a k-d tree), and the plates that may stand in a plate's way (a tree of
// bounds), each checked against a brute-force count on random data with the hard cases built in
// (clusters of noisy normals across cell borders, normals of both signs, boxes that only touch).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/normal_classes.h"
#include "plate/swept_collision.h"

namespace desia {
namespace {

class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  double uniform() {  // [-1, 1)
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state_ >> 11) / 9007199254740992.0 * 2 - 1;
  }
  Vec3 unit() {
    Vec3 v{};
    do v = {uniform(), uniform(), uniform()};
    while (norm(v) < 0.1 || norm(v) > 1);
    return normalized(v);
  }

 private:
  uint64_t state_;
};

// Unit vectors in clusters: a few directions (and their opposites) with noise up to `noise` rad,
// so that groups form by chains and straddle the grid's cells.
std::vector<Vec3> clusteredNormals(uint64_t seed, int directions, int perDirection, double noise) {
  Random random(seed);
  std::vector<Vec3> centres;
  for (int k = 0; k < directions; ++k) centres.push_back(random.unit());
  // Directions whose first component is 0: noise gives it either sign, and the grid files such
  // normals on opposite sides of the origin (the other sign's cells must be searched too).
  centres.push_back({0, 1, 0});
  centres.push_back({0, 0.6, 0.8});
  std::vector<Vec3> normals;
  for (int k = 0; k < perDirection; ++k) {
    for (const Vec3& c : centres) {
      Vec3 v = plus(c, scaled(random.unit(), noise * std::abs(random.uniform())));
      v = normalized(v);
      normals.push_back(k % 2 ? negated(v) : v);
    }
  }
  return normals;
}

double apartUpToSign(const Vec3& a, const Vec3& b) { return std::min(norm(minus(a, b)), norm(plus(a, b))); }

// Single linkage over every pair: the brute-force groups (each normal's smallest group mate).
std::vector<int> bruteForceGroups(const std::vector<Vec3>& normals, double angle) {
  std::vector<int> group(normals.size());
  for (size_t k = 0; k < normals.size(); ++k) group[k] = static_cast<int>(k);
  bool changed = true;
  while (changed) {
    changed = false;
    for (size_t i = 0; i < normals.size(); ++i) {
      for (size_t j = 0; j < normals.size(); ++j) {
        if (group[j] < group[i] && apartUpToSign(normals[i], normals[j]) <= angle) {
          group[i] = group[j];
          changed = true;
        }
      }
    }
  }
  return group;
}

TEST(PlateIndexes, ParallelNormalsAreGroupedAsEveryPairComparedWouldGroupThem) {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const double angle = seed % 2 ? tolerance::kDrawnDirectionRad : tolerance::kComputedDirectionRad;
    // Noise of about the angle: chains that link and gaps that do not, both kinds in each set.
    const std::vector<Vec3> normals = clusteredNormals(seed, 6, 25, angle * (1 + seed % 3));
    const std::vector<int> groups = bruteForceGroups(normals, angle);
    const std::vector<Vec3> snapped = snappedDirections(normals, angle);
    ASSERT_EQ(snapped.size(), normals.size());
    size_t groupCount = 0;
    for (size_t i = 0; i < normals.size(); ++i) {
      groupCount += groups[i] == static_cast<int>(i) ? 1 : 0;
      for (size_t j = i + 1; j < normals.size(); ++j) {
        // One group: one direction (signs kept); two groups: two directions.
        const bool same = apartUpToSign(snapped[i], snapped[j]) == 0;
        ASSERT_EQ(same, groups[i] == groups[j]) << "seed " << seed << ", normals " << i << " and " << j;
      }
    }
    // The sets are not trivial: several groups, and groups of several normals.
    EXPECT_GT(groupCount, 6u) << "seed " << seed;
    EXPECT_LT(groupCount, normals.size() / 2) << "seed " << seed;
  }
}

TEST(PlateIndexes, NearlySquareDirectionsAreSquaredAsEveryPairComparedWouldFindThem) {
  // Directions in a plane (a round top's sides) and in space, a few of them nearly square to others:
  // after snapping, every pair the brute force finds within the angle of square is square.
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Random random(seed);
    const double angle = tolerance::kDrawnDirectionRad;
    std::vector<Vec3> normals;
    for (int k = 0; k < 400; ++k) {
      const double t = 2 * std::acos(-1.0) * k / 400 + angle * 0.3 * random.uniform();
      normals.push_back({std::cos(t), std::sin(t), 0});
    }
    for (int k = 0; k < 200; ++k) normals.push_back(random.unit());
    // A vertical direction just off square to the whole circle.
    normals.push_back(normalized({angle * 0.4, 0, 1}));
    const std::vector<Vec3> snapped = snappedDirections(normals, angle);
    std::set<std::pair<size_t, size_t>> nearlySquare;
    size_t squarePairs = 0;
    for (size_t i = 0; i < normals.size(); ++i) {
      for (size_t j = i + 1; j < normals.size(); ++j) {
        if (apartUpToSign(snapped[i], snapped[j]) == 0) continue;  // one group
        if (std::abs(dot(normals[i], normals[j])) < angle / 2) {
          EXPECT_LT(std::abs(dot(snapped[i], snapped[j])), 1e-7) << "seed " << seed << ": " << i << ", " << j;
          ++squarePairs;
        }
      }
    }
    EXPECT_GT(squarePairs, 400u) << "seed " << seed;  // the vertical one with every side, and more
  }
}

TEST(PlateIndexes, ThePlatesInAPlatesWayAreThoseEveryPlateComparedWouldFind) {
  // Boxes on a jittered grid, some touching exactly, moved along axes and slanted directions: the
  // index visits exactly the boxes that meshCollidesAlong's first test would not rule out.
  Random random(7);
  std::vector<TriangleMesh> meshes;
  for (int i = 0; i < 300; ++i) {
    const Vec3 lo{std::floor(10 * random.uniform()) * 10, std::floor(10 * random.uniform()) * 10,
                  std::floor(4 * random.uniform()) * 10};
    const Vec3 size{5 + 10 * std::abs(random.uniform()), 5 + 10 * std::abs(random.uniform()), 10};
    TriangleMesh box;
    for (int corner = 0; corner < 8; ++corner) {
      box.vertices.push_back({lo[0] + (corner & 1 ? size[0] : 0), lo[1] + (corner & 2 ? size[1] : 0),
                              lo[2] + (corner & 4 ? size[2] : 0)});
    }
    meshes.push_back(box);
  }
  const SweptBoxIndex index(meshes);
  const std::vector<Vec3> directions{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, normalized({1, 1, 0}), normalized({-1, 2, -3})};
  size_t found = 0;
  for (int mover = 0; mover < 300; mover += 7) {
    for (const Vec3& d : directions) {
      std::set<int> visited;
      index.anyInTheWay(mover, d, 0.05, [&](int q) {
        visited.insert(q);
        return false;
      });
      // The box test alone: meshes with no triangles collide only if the boxes allow it.
      for (int q = 0; q < 300; ++q) {
        if (q == mover) continue;
        const TriangleMesh& m = meshes[static_cast<size_t>(mover)];
        const TriangleMesh& o = meshes[static_cast<size_t>(q)];
        bool reaches = true;
        for (int k = 0; k < 3; ++k) {
          double mLo = HUGE_VAL, mHi = -HUGE_VAL, oLo = HUGE_VAL, oHi = -HUGE_VAL;
          for (const auto& p : m.vertices) mLo = std::min(mLo, p[k]), mHi = std::max(mHi, p[k]);
          for (const auto& p : o.vertices) oLo = std::min(oLo, p[k]), oHi = std::max(oHi, p[k]);
          if (d[k] > tolerance::kComponentNoise) mHi = HUGE_VAL;
          if (d[k] < -tolerance::kComponentNoise) mLo = -HUGE_VAL;
          if (oHi <= mLo + 0.05 || mHi <= oLo + 0.05) reaches = false;
        }
        EXPECT_EQ(visited.count(q) == 1, reaches) << "mover " << mover << ", plate " << q;
      }
      found += visited.size();
      // Stopping: the first visit that says so ends the search.
      int visits = 0;
      const bool stopped = index.anyInTheWay(mover, d, 0.05, [&](int) { return ++visits == 1; });
      EXPECT_EQ(stopped, !visited.empty());
      EXPECT_LE(visits, 1);
    }
  }
  EXPECT_GT(found, 100u);
}

}  // namespace
}  // namespace desia
