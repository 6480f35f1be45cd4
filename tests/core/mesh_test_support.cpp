// SPDX-License-Identifier: GPL-3.0-or-later
// What the mesh assembly tests share (mesh_test_support.h).
#include "mesh_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "desia/export.h"
#include "test_support.h"

namespace desia::testing {

AssemblyDocument readDocument(const std::string& path) {
  return parseAssemblyText(readFileText(projectPath(path)), path);
}

std::string exported(const AssemblyDocument& document, const char* format, int part) {
  ExportSettings settings;
  settings.mesh.part = part;
  return exportFiles(document, exportFormatNamed(format), settings).front();
}

CheckOptions bothTests() {
  CheckOptions options;
  options.method = CheckMethod::Both;
  return options;
}

MeshAssembly meshesOf(const std::vector<MeshFile>& files, LengthUnit unit) {
  return buildMeshAssembly(readMeshParts(files, unit));
}

// The OBJ text with every vertex turned by `rotation` and divided by `unitInMm` (so that reading it
// in that unit gives back millimetres).
std::string transformedObj(const std::string& obj, const std::array<Vec3, 3>& rotation, double unitInMm) {
  std::istringstream in(obj);
  std::ostringstream out;
  std::string line;
  char buffer[128];
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) {
      Vec3 p{};
      std::istringstream(line.substr(2)) >> p[0] >> p[1] >> p[2];
      Vec3 q{};
      for (int i = 0; i < 3; ++i) q[i] = (rotation[i][0] * p[0] + rotation[i][1] * p[1] + rotation[i][2] * p[2]) / unitInMm;
      std::snprintf(buffer, sizeof buffer, "v %.17g %.17g %.17g", q[0], q[1], q[2]);
      out << buffer << '\n';
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

// A uniformly random rotation (a random unit quaternion) from a seeded generator.
std::array<Vec3, 3> randomRotation(std::mt19937& random) {
  std::normal_distribution<double> gauss;
  double q[4];
  double length = 0;
  for (double& c : q) c = gauss(random), length += c * c;
  length = std::sqrt(length);
  const double w = q[0] / length, x = q[1] / length, y = q[2] / length, z = q[3] / length;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

// --- An independent check of a plan ------------------------------------------------------------

// Generalized winding number of a closed mesh around p (solid angles of its triangles, Van
// Oosterom and Strackee): about 1 inside, 0 outside. Nothing of the sweep or the ray test.
double windingNumber(const TriangleMesh& mesh, const Vec3& p) {
  double total = 0;
  for (const auto& t : mesh.triangles) {
    Vec3 a, b, c;
    for (int i = 0; i < 3; ++i) {
      a[i] = mesh.vertices[t[0]][i] - p[i];
      b[i] = mesh.vertices[t[1]][i] - p[i];
      c[i] = mesh.vertices[t[2]][i] - p[i];
    }
    const auto length = [](const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
    const auto dotted = [](const Vec3& u, const Vec3& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    const double la = length(a), lb = length(b), lc = length(c);
    const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    const double denominator = la * lb * lc + dotted(a, b) * lc + dotted(b, c) * la + dotted(c, a) * lb;
    total += 2 * std::atan2(det, denominator);
  }
  return total / (4 * M_PI);
}

namespace {

// Points inside the part, `depth` below the middle of each triangle.
std::vector<Vec3> samplesInside(const TriangleMesh& mesh, double depth) {
  std::vector<Vec3> samples;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Vec3 n{(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
           (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
           (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length == 0) continue;
    Vec3 p;
    for (int i = 0; i < 3; ++i) p[i] = (a[i] + b[i] + c[i]) / 3 - n[i] / length * depth;
    if (windingNumber(mesh, p) > 0.5) samples.push_back(p);
  }
  return samples;
}

struct Extent {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

Extent extentOf(const TriangleMesh& mesh, const Vec3& offset) {
  Extent e;
  for (const Vec3& v : mesh.vertices) {
    for (int i = 0; i < 3; ++i) e.lo[i] = std::min(e.lo[i], v[i] + offset[i]), e.hi[i] = std::max(e.hi[i], v[i] + offset[i]);
  }
  return e;
}

bool apart(const Extent& a, const Extent& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.lo[i] > b.hi[i] || b.lo[i] > a.hi[i]) return true;
  }
  return false;
}

// The smallest side of any part's box, over 4: the step of a replay.
double replayStep(const MeshAssembly& meshes) {
  double smallest = 1e300;
  for (const MeshPart& part : meshes.parts) {
    const Extent e = extentOf(part.mesh, {0, 0, 0});
    for (int i = 0; i < 3; ++i) smallest = std::min(smallest, e.hi[i] - e.lo[i]);
  }
  return smallest / 4;
}

// "" when no sample of `mover` (at offset `at`) lies inside `still` (at `stillAt`) nor one of
// `still`'s inside `mover`; else which enters which. *touching: their boxes meet.
std::string collision(const MeshAssembly& meshes, const std::vector<std::vector<Vec3>>& samples, size_t mover,
                      const Vec3& at, size_t still, const Vec3& stillAt, bool* touching) {
  const TriangleMesh& moving = meshes.parts[mover].mesh;
  const TriangleMesh& staying = meshes.parts[still].mesh;
  *touching = !apart(extentOf(moving, at), extentOf(staying, stillAt));
  if (!*touching) return "";
  const Vec3 relative{at[0] - stillAt[0], at[1] - stillAt[1], at[2] - stillAt[2]};
  // A point outside a part's box is outside the part: only those inside need a winding number.
  const Extent stayingBox = extentOf(staying, {0, 0, 0}), movingBox = extentOf(moving, {0, 0, 0});
  const auto inBox = [](const Extent& box, const Vec3& p) {
    for (int i = 0; i < 3; ++i) {
      if (p[i] < box.lo[i] || p[i] > box.hi[i]) return false;
    }
    return true;
  };
  for (const Vec3& s : samples[mover]) {
    const Vec3 p{s[0] + relative[0], s[1] + relative[1], s[2] + relative[2]};
    if (inBox(stayingBox, p) && windingNumber(staying, p) > 0.5) {
      return "part " + std::to_string(meshes.parts[mover].id) + " enters part " + std::to_string(meshes.parts[still].id);
    }
  }
  for (const Vec3& s : samples[still]) {
    const Vec3 p{s[0] - relative[0], s[1] - relative[1], s[2] - relative[2]};
    if (inBox(movingBox, p) && windingNumber(moving, p) > 0.5) {
      return "part " + std::to_string(meshes.parts[still].id) + " is entered by part " + std::to_string(meshes.parts[mover].id);
    }
  }
  return "";
}

std::vector<std::vector<Vec3>> samplesOf(const MeshAssembly& meshes) {
  std::vector<std::vector<Vec3>> samples;
  for (const MeshPart& part : meshes.parts) samples.push_back(samplesInside(part.mesh, 20 * meshes.tolerance));
  return samples;
}

}  // namespace

// "" when the plan's single-part removals, replayed in small steps, never put a sample point of a
// moving part inside a part still in place (or one of theirs inside it); else what collided.
std::string replayFailure(const MeshAssembly& meshes, const DisassemblyPlan& plan) {
  const size_t n = meshes.parts.size();
  const std::vector<std::vector<Vec3>> samples = samplesOf(meshes);
  const double step = replayStep(meshes);
  std::vector<bool> present(n, true);
  for (const Removal& removal : plan.removals) {
    const size_t mover = static_cast<size_t>(removal.part);
    Vec3 offset{0, 0, 0};
    for (const Move& move : removal.path) {
      const bool out = move.length == 0;
      for (double travelled = 0;; travelled += step) {
        const double t = out ? travelled : std::min(travelled, move.length);
        Vec3 at;
        for (int i = 0; i < 3; ++i) at[i] = offset[i] + move.direction[i] * t;
        bool clearOfAll = true;
        for (size_t other = 0; other < n; ++other) {
          if (!present[other] || other == mover) continue;
          bool touching = false;
          const std::string failure = collision(meshes, samples, mover, at, other, {0, 0, 0}, &touching);
          if (!failure.empty()) return failure;
          clearOfAll = clearOfAll && !touching;
        }
        if ((out && clearOfAll) || (!out && t >= move.length)) {
          offset = at;
          break;
        }
      }
    }
    present[mover] = false;
  }
  return "";
}

std::string replayMovesFailure(const MeshAssembly& meshes, const DisassemblyPlan& plan) {
  const size_t n = meshes.parts.size();
  const std::vector<std::vector<Vec3>> samples = samplesOf(meshes);
  const double step = replayStep(meshes);
  std::vector<Vec3> offsets(n, Vec3{0, 0, 0});
  std::vector<int> group(n, 0);
  int groups = 1;
  for (size_t m = 0; m < plan.moves.size(); ++m) {
    const GroupMove& move = plan.moves[m];
    const int from = group[static_cast<size_t>(move.parts.front())];
    std::vector<bool> moving(n, false);
    for (int part : move.parts) moving[static_cast<size_t>(part)] = true;
    for (double travelled = step;; travelled += step) {
      const double t = move.out ? travelled : std::min(travelled, move.length);
      bool clearOfAll = true;
      for (int part : move.parts) {
        const size_t p = static_cast<size_t>(part);
        const Vec3 at{offsets[p][0] + move.direction[0] * t, offsets[p][1] + move.direction[1] * t,
                      offsets[p][2] + move.direction[2] * t};
        for (size_t other = 0; other < n; ++other) {
          if (moving[other] || group[other] != from) continue;
          bool touching = false;
          const std::string failure = collision(meshes, samples, p, at, other, offsets[other], &touching);
          if (!failure.empty()) return "move " + std::to_string(m + 1) + ": " + failure;
          clearOfAll = clearOfAll && !touching;
        }
      }
      if ((move.out && clearOfAll) || (!move.out && t >= move.length)) {
        for (int part : move.parts) {
          const size_t p = static_cast<size_t>(part);
          for (int i = 0; i < 3; ++i) offsets[p][i] += move.direction[i] * t;
          if (move.out) group[p] = groups;
        }
        break;
      }
    }
    if (move.out) ++groups;
  }
  std::vector<int> sizes(static_cast<size_t>(groups), 0);
  for (int g : group) ++sizes[static_cast<size_t>(g)];
  for (int size : sizes) {
    if (plan.complete && size > 1) return std::to_string(size) + " parts are left together";
  }
  return "";
}

}  // namespace desia::testing
