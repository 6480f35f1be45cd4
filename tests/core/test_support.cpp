// SPDX-License-Identifier: GPL-3.0-or-later
#include "test_support.h"

#include "desia/error.h"

#include <array>
#include <cmath>
#include <cctype>
#include <fstream>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace desia::testing {

std::string referencePath(const std::string& relative) { return std::string(DESIA_TEST_DATA_DIR) + "/" + relative; }

std::string projectPath(const std::string& relative) { return std::string(DESIA_PROJECT_DIR) + "/" + relative; }

namespace {
constexpr std::array<std::array<int, 3>, 6> kNeighbours{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
}  // namespace

bool tradeOneVoxel(VoxelGrid& grid, std::mt19937& random) {
  const int64_t i = static_cast<int64_t>(random() % static_cast<uint32_t>(grid.voxelCount()));
  const int label = grid.labelAt(i);
  if (label == 0) return false;
  const Int3 c = grid.coordinates(i);
  const auto& step = kNeighbours[random() % 6];
  const int x = c.x + step[0], y = c.y + step[1], z = c.z + step[2];
  if (!grid.inside(x, y, z)) return false;
  const int other = grid.label(x, y, z);
  if (other == 0 || other == label) return false;
  grid.setLabelAt(i, other);
  try {
    validateVoxelParts(grid, "variant");
  } catch (const Error&) {
    grid.setLabelAt(i, label);
    return false;
  }
  return true;
}

std::string readFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("test fixture missing: " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

AssemblyDocument loadReference(const std::string& relative) {
  return parseAssemblyText(readFileText(referencePath(relative)), relative);
}

VoxelGrid gridFromLayers(const std::vector<std::vector<std::string>>& layers) {
  std::string text;
  std::istringstream firstRow(layers.at(0).at(0));
  int nx = 0;
  for (std::string token; firstRow >> token;) ++nx;
  text = std::to_string(nx) + " " + std::to_string(layers[0].size()) + " " + std::to_string(layers.size()) + "\n";
  for (const auto& layer : layers) {
    for (const auto& row : layer) text += row + "\n";
    text += "\n";
  }
  return parsePuz(text, "test");
}

std::string testNameFromPath(const std::string& path) {
  std::string name = path.substr(path.find('/') + 1);
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

std::vector<std::vector<std::string>> sChannelLayers() {
  return {
      {"2 2 2 2 2", "2 2 2 2 2", "2 2 2 2 2", "2 2 2 2 2"},
      {"2 2 2 2 2", "2 1 0 2 2", "2 2 0 0 0", "2 2 2 2 2"},
      {"2 2 2 2 2", "2 2 2 2 2", "2 2 2 2 2", "2 2 2 2 2"},
  };
}

std::vector<int> idsOf(const Assembly& assembly, const std::vector<int>& parts) {
  std::vector<int> ids;
  for (int part : parts) ids.push_back(assembly.parts[part].id);
  return ids;
}

std::vector<std::string> labelsOf(const std::vector<Vec3>& directions) {
  std::vector<std::string> labels;
  for (const Vec3& d : directions) labels.push_back(directionLabel(d));
  return labels;
}

void ExpectInterlocking(const AssemblyDocument& document, const InterlockingResult& result, int keyId,
                        const std::vector<std::string>& keyDirections) {
  EXPECT_EQ(result.verdict, Verdict::Interlocking) << result.reason;
  ASSERT_GE(result.key, 0) << result.reason;
  EXPECT_EQ(document.assembly.parts[result.key].id, keyId);
  EXPECT_EQ(labelsOf(result.keyDirections), keyDirections);
  EXPECT_FALSE(result.hasWitness);
}

namespace {

bool collidesAt(const VoxelGrid& grid, const std::vector<bool>& present, int partId, int dx, int dy, int dz) {
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        if (grid.label(x, y, z) != partId) continue;
        const int px = x + dx, py = y + dy, pz = z + dz;
        if (!grid.inside(px, py, pz)) continue;
        const int other = grid.label(px, py, pz);
        if (other != 0 && other != partId && present[other - 1]) return true;
      }
    }
  }
  return false;
}

}  // namespace

std::string verifyRemoval(const VoxelGrid& grid, const std::vector<bool>& present, int partId,
                          const std::vector<Move>& path) {
  int offset[3] = {0, 0, 0};
  auto step = [&](const Vec3& d) {
    for (int k = 0; k < 3; ++k) offset[k] += static_cast<int>(d[k]);
    return !collidesAt(grid, present, partId, offset[0], offset[1], offset[2]);
  };
  for (const Move& move : path) {
    for (int s = 0; s < move.steps; ++s) {
      if (!step(move.direction)) return "part " + std::to_string(partId) + " collides during " + directionLabel(move.direction);
    }
  }
  if (path.empty()) return "part " + std::to_string(partId) + " has an empty path";
  const int far = grid.nx() + grid.ny() + grid.nz();
  for (int s = 0; s < far; ++s) {
    if (!step(path.back().direction)) return "part " + std::to_string(partId) + " collides after its path, going to infinity";
  }
  return "";
}

std::vector<std::vector<std::array<int, 3>>> partCells(const VoxelGrid& grid) {
  std::vector<std::vector<std::array<int, 3>>> cells(static_cast<size_t>(grid.maxLabel()));
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        if (grid.label(x, y, z) > 0) cells[static_cast<size_t>(grid.label(x, y, z) - 1)].push_back({x, y, z});
      }
    }
  }
  return cells;
}

std::string replayVoxelMoves(const VoxelGrid& grid, const std::vector<GroupMove>& moves, bool complete) {
  using Cell = std::array<int, 3>;
  const int parts = grid.maxLabel();
  std::vector<std::vector<Cell>> cells = partCells(grid);
  std::vector<int> group(static_cast<size_t>(parts), 0);
  int groups = 1;
  for (size_t m = 0; m < moves.size(); ++m) {
    const GroupMove& move = moves[m];
    const std::string where = "move " + std::to_string(m + 1) + ": ";
    if (move.parts.empty()) return where + "moves no part";
    int axis = -1, sign = 0, nonZero = 0;
    for (int a = 0; a < 3; ++a) {
      if (move.direction[a] == 0) continue;
      ++nonZero;
      axis = a;
      sign = move.direction[a] > 0 ? 1 : -1;
      if (std::abs(move.direction[a]) != 1) return where + "the direction is not a unit axis";
    }
    if (nonZero != 1) return where + "the direction is not a unit axis";
    if (!move.out && move.steps < 1) return where + "moves by " + std::to_string(move.steps) + " units";
    std::set<int> moving;
    for (int part : move.parts) {
      if (part < 0 || part >= parts || !moving.insert(part).second) return where + "lists a part twice or a part that does not exist";
      if (group[static_cast<size_t>(part)] != group[static_cast<size_t>(move.parts[0])]) return where + "moves parts of different sub-assemblies";
    }
    const int together = group[static_cast<size_t>(move.parts[0])];
    std::set<Cell> still;
    int stillMin = std::numeric_limits<int>::max(), stillMax = std::numeric_limits<int>::min();
    for (int part = 0; part < parts; ++part) {
      if (group[static_cast<size_t>(part)] != together || moving.count(part)) continue;
      for (const Cell& c : cells[static_cast<size_t>(part)]) {
        still.insert(c);
        stillMin = std::min(stillMin, c[axis]);
        stillMax = std::max(stillMax, c[axis]);
      }
    }
    if (still.empty()) return where + "moves a whole sub-assembly";
    auto pastTheRest = [&] {
      for (int part : moving) {
        for (const Cell& c : cells[static_cast<size_t>(part)]) {
          if (sign > 0 ? c[axis] <= stillMax : c[axis] >= stillMin) return false;
        }
      }
      return true;
    };
    for (int step = 0; move.out ? !pastTheRest() : step < move.steps; ++step) {
      for (int part : moving) {
        for (Cell& c : cells[static_cast<size_t>(part)]) {
          c[axis] += sign;
          if (still.count(c)) return where + "part " + std::to_string(part + 1) + " runs into a part of its sub-assembly";
        }
      }
    }
    if (move.out) {
      for (int part : moving) group[static_cast<size_t>(part)] = groups;
      ++groups;
    }
  }
  if (complete) {
    std::map<int, int> sizes;
    for (int g : group) ++sizes[g];
    for (const auto& [g, size] : sizes) {
      if (size > 1) return "the plan ends with " + std::to_string(size) + " parts still together";
    }
  }
  return "";
}

std::string verifyPlan(const VoxelGrid& grid, const Assembly& assembly, const DisassemblyPlan& plan) {
  if (!plan.complete) return "plan incomplete";
  if (!plan.moves.empty()) {
    const std::string problem = replayVoxelMoves(grid, plan.moves, true);
    if (!problem.empty()) return problem;
  }
  if (!plan.singlePartPaths) return "";
  if (static_cast<int>(plan.removals.size()) != assembly.partCount()) return "plan does not list every part";
  std::vector<bool> present(assembly.partCount(), true);
  for (size_t i = 0; i + 1 < plan.removals.size(); ++i) {
    const Removal& removal = plan.removals[i];
    const std::string problem = verifyRemoval(grid, present, assembly.parts[removal.part].id, removal.path);
    if (!problem.empty()) return problem;
    present[removal.part] = false;
  }
  return plan.removals.back().path.empty() ? "" : "the last part should stay in place";
}

// Empty when every directed edge (a, b) of the indexed mesh occurs exactly once and (b, a) exactly
// once: each edge in exactly two triangles, in opposite directions (a closed, oriented 2-manifold
// surface away from its vertices).
std::string manifoldProblem(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const int reverseCount = reverse == directed.end() ? 0 : reverse->second;
    if (count != 1 || reverseCount != 1) {
      return "edge " + std::to_string(edge.first) + "->" + std::to_string(edge.second) + " used " +
             std::to_string(count) + " times, reversed " + std::to_string(reverseCount) + " times";
    }
  }
  return "";
}

// Divergence theorem: the volume enclosed by an outward-oriented closed surface is the sum of the
// signed volumes of the tetrahedra (origin, a, b, c).
double enclosedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    const std::array<double, 3>& a = mesh.vertices[t[0]];
    const std::array<double, 3>& b = mesh.vertices[t[1]];
    const std::array<double, 3>& c = mesh.vertices[t[2]];
    volume +=
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6;
}

uint32_t bitwiseCrc32(const std::string& data) {
  uint32_t crc = 0xFFFFFFFFu;
  for (const char c : data) {
    crc ^= static_cast<uint8_t>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::array<Vec3, 3> rotation(double ax, double ay, double az) {
  auto mul = [](const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    std::array<Vec3, 3> r{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    }
    return r;
  };
  const std::array<Vec3, 3> x{{{1, 0, 0}, {0, std::cos(ax), -std::sin(ax)}, {0, std::sin(ax), std::cos(ax)}}};
  const std::array<Vec3, 3> y{{{std::cos(ay), 0, std::sin(ay)}, {0, 1, 0}, {-std::sin(ay), 0, std::cos(ay)}}};
  const std::array<Vec3, 3> z{{{std::cos(az), -std::sin(az), 0}, {std::sin(az), std::cos(az), 0}, {0, 0, 1}}};
  return mul(z, mul(y, x));
}

std::vector<Plate> turnedPlates(std::vector<Plate> plates, const std::array<Vec3, 3>& r, double scale, int decimals) {
  const double unit = std::pow(10.0, decimals);
  for (Plate& plate : plates) {
    for (std::vector<Loop>* face : {&plate.bottom, &plate.top}) {
      for (Loop& loop : *face) {
        for (Vec3& p : loop) {
          Vec3 q{};
          for (int i = 0; i < 3; ++i) {
            q[i] = (r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2]) * scale;
            if (decimals > 0) q[i] = std::round(q[i] * unit) / unit;
          }
          p = q;
        }
      }
    }
  }
  return plates;
}

}  // namespace desia::testing
