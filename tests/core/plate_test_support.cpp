// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate_test_support.h"

#include <cmath>

#include "desia/design_io.h"
#include "test_support.h"

namespace desia::testing {

AssemblyDocument loadPlateExample(const std::string& name) {
  const std::string path = "examples/plate/" + name;
  return parseAssemblyText(readFileText(projectPath(path)), path);
}

Plate board(int id, const Vec3& lo, const Vec3& hi) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) axis = hi[k] - lo[k] < hi[axis] - lo[axis] ? k : axis;
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;  // (u, w, axis) right-handed
  Plate plate;
  plate.id = id;
  Loop bottom, top;
  const std::array<std::array<double, 2>, 4> corners{{{lo[u], lo[w]}, {hi[u], lo[w]}, {hi[u], hi[w]}, {lo[u], hi[w]}}};
  for (const std::array<double, 2>& corner : corners) {
    Vec3 p{0, 0, 0};
    p[u] = corner[0];
    p[w] = corner[1];
    p[axis] = lo[axis];
    bottom.push_back(p);
    p[axis] = hi[axis];
    top.push_back(p);
  }
  plate.bottom = {bottom};
  plate.top = {top};
  return plate;
}

double meshVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles)
    volume += dot(mesh.vertices[t[0]], cross(mesh.vertices[t[1]], mesh.vertices[t[2]])) / 6.0;
  return volume;
}

double plateVolume(const Plate& plate) { return meshVolume(plateMesh(plate)); }

namespace {

// The first face's outline's normal by Newell's sum over its sides (the core's plateThicknessAxis is
// what this check is independent of; its sign does not matter to contains()).
Vec3 outlineNormal(const Loop& loop) {
  Vec3 sum{0, 0, 0};
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = loop[i];
    const Vec3& q = loop[(i + 1) % loop.size()];
    sum = plus(sum, Vec3{(p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]), (p[0] - q[0]) * (p[1] + q[1])});
  }
  return normalized(sum);
}

}  // namespace

PlateInside::PlateInside(const Plate& plate)
    : axis_(outlineNormal(plate.bottom[0])),
      base_(plate.bottom[0][0]),
      u_(normalized(cross(axis_, std::abs(axis_[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}))),
      v_(cross(axis_, u_)),
      thickness_(dot(minus(plate.top[0][0], base_), axis_)) {
  auto projected = [&](const Vec3& p) {
    const Vec3 q = minus(p, base_);
    return std::array<double, 2>{dot(q, u_), dot(q, v_)};
  };
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    ProjectedLoop loop;
    for (size_t i = 0; i < plate.bottom[l].size(); ++i) {
      loop.first.push_back(projected(plate.bottom[l][i]));
      loop.second.push_back(projected(plate.top[l][i]));
    }
    loops_.push_back(std::move(loop));
  }
  for (const Plate& piece : plate.attached) attached_.emplace_back(piece);
}

bool PlateInside::contains(const Vec3& point) const {
  for (const PlateInside& piece : attached_) {
    if (piece.contains(point)) return true;
  }
  const Vec3 offset = minus(point, base_);
  const double height = dot(offset, axis_);
  if (height * thickness_ <= 0 || std::abs(height) >= std::abs(thickness_)) return false;
  const double f = height / thickness_, px = dot(offset, u_), py = dot(offset, v_);
  bool in = false;  // even-odd over every loop: holes count
  for (const ProjectedLoop& loop : loops_) {
    auto at = [&](size_t i) {
      return std::array<double, 2>{loop.first[i][0] + f * (loop.second[i][0] - loop.first[i][0]),
                                   loop.first[i][1] + f * (loop.second[i][1] - loop.first[i][1])};
    };
    for (size_t i = 0, j = loop.first.size() - 1; i < loop.first.size(); j = i++) {
      const auto a = at(i), b = at(j);
      if ((a[1] > py) != (b[1] > py) && px < (b[0] - a[0]) * (py - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
    }
  }
  return in;
}

std::vector<Vec3> samplesInside(const Plate& plate, const Vec3& origin, const std::array<SampleAxis, 3>& axes) {
  const PlateInside inside(plate);
  constexpr std::array<double, 3> kOffsets{0.013, 0.017, 0.011};  // mm: off any round-numbered face
  std::vector<Vec3> samples;
  for (double a = axes[0].from + kOffsets[0]; a < axes[0].to; a += axes[0].step) {
    for (double b = axes[1].from + kOffsets[1]; b < axes[1].to; b += axes[1].step) {
      for (double c = axes[2].from + kOffsets[2]; c < axes[2].to; c += axes[2].step) {
        const Vec3 p = plus(origin, plus(scaled(axes[0].direction, a),
                                         plus(scaled(axes[1].direction, b), scaled(axes[2].direction, c))));
        if (inside.contains(p)) samples.push_back(p);
      }
    }
  }
  return samples;
}

bool steppedCollision(const std::vector<Vec3>& samples, const Plate& obstacle, const Vec3& d, double step,
                      double reach) {
  const PlateInside standing(obstacle);
  for (double t = step / 2; t < reach; t += step) {
    for (const Vec3& p : samples) {
      if (standing.contains(plus(p, scaled(d, t)))) return true;
    }
  }
  return false;
}

std::vector<Plate> jointedInRemovalOrder(const PlateDesignResult& result) {
  std::vector<Plate> inOrder;
  for (int index : result.order) inOrder.push_back(result.jointedPlates.at(static_cast<size_t>(index)));
  return inOrder;
}

AssemblyDocument writtenPlateResult(const std::vector<Plate>& plates, const PlateDesignResult& result,
                                    const std::string& name) {
  AssemblyDocument input;
  input.kind = AssemblyKind::Plate;
  input.name = name;
  input.plates = plates;
  return parseJsonDocument(plateDesignToJson(input, result), name + " plan");
}

std::array<CheckReport, 2> checkedByBothMethods(const AssemblyDocument& document) {
  std::array<CheckReport, 2> reports;
  const CheckMethod methods[] = {CheckMethod::Graphs, CheckMethod::Inequalities};
  for (size_t k = 0; k < reports.size(); ++k) {
    CheckOptions options;
    options.method = methods[k];
    reports[k] = checkDocument(document, options);
  }
  return reports;
}

}  // namespace desia::testing
