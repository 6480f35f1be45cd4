// SPDX-License-Identifier: GPL-3.0-or-later
// Triangles, box trees and point queries of the mesh kind.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "desia/error.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {

std::vector<Triangle> trianglesOf(const TriangleMesh& mesh) {
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    Triangle triangle;
    for (int k = 0; k < 3; ++k) triangle.p[static_cast<size_t>(k)] = mesh.vertices[static_cast<size_t>(t[static_cast<size_t>(k)])];
    const Vec3 n = cross(minus(triangle.p[1], triangle.p[0]), minus(triangle.p[2], triangle.p[0]));
    triangle.twiceArea = norm(n);
    if (triangle.twiceArea > 0) triangle.normal = scaled(n, 1.0 / triangle.twiceArea);
    triangles.push_back(triangle);
  }
  return triangles;
}

namespace {

constexpr int kLeafBoxes = 4;

Vec3 centreOf(const Box& box) {
  return {(box.lo[0] + box.hi[0]) / 2, (box.lo[1] + box.hi[1]) / 2, (box.lo[2] + box.hi[2]) / 2};
}

}  // namespace

BoxTree::BoxTree(const std::vector<Box>& boxes) : boxes_(boxes), order_(boxes.size()) {
  std::iota(order_.begin(), order_.end(), 0);
  if (boxes_.empty()) return;
  std::vector<Vec3> centres;
  centres.reserve(boxes_.size());
  for (const Box& box : boxes_) centres.push_back(centreOf(box));
  nodes_.push_back({Box{}, -1, -1, 0, static_cast<int>(boxes_.size())});
  std::vector<int> pending{0};
  while (!pending.empty()) {
    const int index = pending.back();
    pending.pop_back();
    Node node = nodes_[static_cast<size_t>(index)];
    Box centreBox;
    for (int k = node.first; k < node.first + node.count; ++k) {
      node.box.add(boxes_[static_cast<size_t>(order_[static_cast<size_t>(k)])]);
      centreBox.add(centres[static_cast<size_t>(order_[static_cast<size_t>(k)])]);
    }
    if (node.count > kLeafBoxes) {
      int axis = 0;
      for (int i = 1; i < 3; ++i) {
        if (centreBox.hi[i] - centreBox.lo[i] > centreBox.hi[axis] - centreBox.lo[axis]) axis = i;
      }
      const auto begin = order_.begin() + node.first, end = begin + node.count, middle = begin + node.count / 2;
      std::nth_element(begin, middle, end, [&](int a, int b) {
        const double ca = centres[static_cast<size_t>(a)][axis], cb = centres[static_cast<size_t>(b)][axis];
        return ca < cb || (ca == cb && a < b);
      });
      node.left = static_cast<int>(nodes_.size());
      node.right = node.left + 1;
      const int half = node.count / 2;
      nodes_.push_back({Box{}, -1, -1, node.first, half});
      nodes_.push_back({Box{}, -1, -1, node.first + half, node.count - half});
      pending.push_back(node.left);
      pending.push_back(node.right);
    }
    nodes_[static_cast<size_t>(index)] = node;
  }
}

namespace {

std::vector<Box> boxesOf(const std::vector<Triangle>& triangles) {
  std::vector<Box> boxes;
  boxes.reserve(triangles.size());
  for (const Triangle& t : triangles) boxes.push_back(t.box());
  return boxes;
}

}  // namespace

PartGeometry::PartGeometry(const TriangleMesh& mesh)
    : triangles(trianglesOf(mesh)), tree(boxesOf(triangles)) {
  box = tree.bounds();
}

std::vector<PartGeometry> partGeometries(const std::vector<MeshPart>& parts) {
  std::vector<PartGeometry> geometry;
  geometry.reserve(parts.size());
  for (const MeshPart& part : parts) geometry.emplace_back(part.mesh);
  return geometry;
}

std::string pointText(const Vec3& p) {
  std::ostringstream out;
  out << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
  return out.str();
}

const std::vector<PartGeometry>& geometryOf(const MeshAssembly& meshes) {
  if (!meshes.geometry || meshes.geometry->size() != meshes.parts.size()) {
    throw Error(ErrorCode::Internal, "a mesh assembly not made by buildMeshAssembly");
  }
  return *meshes.geometry;
}

double pointTriangleDistance(const Vec3& p, const Triangle& t) {
  const Vec3 &a = t.p[0], &b = t.p[1], &c = t.p[2];
  const Vec3 ab = minus(b, a), ac = minus(c, a), ap = minus(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(ap);
  const Vec3 bp = minus(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(minus(p, plus(a, scaled(ab, d1 / (d1 - d3)))));
  const Vec3 cp = minus(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(minus(p, plus(a, scaled(ac, d2 / (d2 - d6)))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return norm(minus(p, plus(b, scaled(minus(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))))));
  }
  const double sum = va + vb + vc;
  if (sum == 0) return norm(ap);  // a triangle of no area: its corners were tried above
  return norm(minus(p, plus(a, plus(scaled(ab, vb / sum), scaled(ac, vc / sum)))));
}

bool pointInside(const Vec3& p, const PartGeometry& part) {
  // An irrational-looking direction: no face of a drawn model is parallel to it, and a ray along
  // it meets an edge or a vertex only by accident of measure zero.
  const Vec3 ray = normalized(Vec3{0.5773502691896258, 0.4082482904638631, 0.7071067811865476});
  int crossings = 0;
  for (const Triangle& t : part.triangles) {
    // Möller–Trumbore: p + s·ray = a + u·e1 + v·e2 with s > 0, u, v >= 0, u + v <= 1.
    const Vec3 e1 = minus(t.p[1], t.p[0]), e2 = minus(t.p[2], t.p[0]);
    const Vec3 h = cross(ray, e2);
    const double det = dot(e1, h);
    if (det == 0) continue;
    const Vec3 s = minus(p, t.p[0]);
    const double u = dot(s, h) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 q = cross(s, e1);
    const double v = dot(ray, q) / det;
    if (v < 0 || u + v > 1) continue;
    if (dot(e2, q) / det > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace desia::mesh
