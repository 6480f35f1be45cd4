// SPDX-License-Identifier: GPL-3.0-or-later
// Each part of a mesh assembly must be a closed solid with a consistent, outward orientation: every
// edge used once in each direction (an open edge or a flipped triangle is named), and a positive
// volume (a part drawn inside out is turned, as CAD exports sometimes are).
#include <algorithm>
#include <cmath>
#include <tuple>
#include <sstream>

#include "desia/error.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {
namespace {

struct DirectedEdge {
  int from, to, triangle;
  bool operator<(const DirectedEdge& other) const {
    const auto key = [](const DirectedEdge& e) {
      return std::make_tuple(std::min(e.from, e.to), std::max(e.from, e.to), e.from, e.triangle);
    };
    return key(*this) < key(other);
  }
};

double signedVolumeTimesSix(const TriangleMesh& mesh) {
  double volume = 0;
  const Vec3& origin = mesh.vertices.front();  // near the part: less cancellation than the origin
  for (const auto& t : mesh.triangles) {
    const Vec3 a = minus(mesh.vertices[static_cast<size_t>(t[0])], origin);
    const Vec3 b = minus(mesh.vertices[static_cast<size_t>(t[1])], origin);
    const Vec3 c = minus(mesh.vertices[static_cast<size_t>(t[2])], origin);
    volume += dot(a, cross(b, c));
  }
  return volume;
}

}  // namespace

std::string partLabel(const MeshPart& part) {
  std::string label = part.source + ": part " + std::to_string(part.id);
  if (!part.name.empty()) label += " ('" + part.name + "')";
  return label;
}

void requireClosedOrientedPart(MeshPart& part, double emptyVolume) {
  const TriangleMesh& mesh = part.mesh;
  if (mesh.triangles.empty()) throwBadInput(partLabel(part), "has no triangles");
  for (const Vec3& v : mesh.vertices) {
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
      throwBadInput(partLabel(part), "has a coordinate that is not finite");
    }
  }
  std::vector<DirectedEdge> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      edges.push_back({mesh.triangles[t][static_cast<size_t>(k)], mesh.triangles[t][static_cast<size_t>((k + 1) % 3)],
                       static_cast<int>(t)});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t k = 0; k < edges.size();) {
    size_t end = k + 1;
    const int low = std::min(edges[k].from, edges[k].to), high = std::max(edges[k].from, edges[k].to);
    while (end < edges.size() && std::min(edges[end].from, edges[end].to) == low &&
           std::max(edges[end].from, edges[end].to) == high) {
      ++end;
    }
    int forward = 0;
    for (size_t m = k; m < end; ++m) forward += edges[m].from == low ? 1 : 0;
    const int backward = static_cast<int>(end - k) - forward;
    const auto edge = [&] {
      return "the edge from vertex " + std::to_string(low + 1) + " " + pointText(mesh.vertices[static_cast<size_t>(low)]) +
             " to vertex " + std::to_string(high + 1) + " " + pointText(mesh.vertices[static_cast<size_t>(high)]);
    };
    if ((end - k) % 2 == 1) {
      throwBadInput(partLabel(part), "is not closed: " + edge() + " belongs to " + std::to_string(end - k) +
                                         " triangle" + (end - k == 1 ? "" : "s") + " (triangle " +
                                         std::to_string(edges[k].triangle + 1) + ")");
    }
    if (forward != backward) {
      throwBadInput(partLabel(part), "is not consistently oriented: " + edge() + " is used " + std::to_string(forward) +
                                         " times in one direction and " + std::to_string(backward) +
                                         " in the other (triangle " + std::to_string(edges[k].triangle + 1) +
                                         " is flipped, or a neighbour is)");
    }
    k = end;
  }
  const double volume = signedVolumeTimesSix(mesh) / 6;
  if (std::abs(volume) <= emptyVolume) throwBadInput(partLabel(part), "encloses no volume");
  if (volume < 0) {
    for (auto& t : part.mesh.triangles) std::swap(t[1], t[2]);  // drawn inside out: turned
  }
}

}  // namespace desia::mesh
