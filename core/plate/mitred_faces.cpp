// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/mitred_faces.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"

namespace desia {
namespace mitred {
namespace {

constexpr size_t kMaxFaces = 10000;  // the plate document's own limit

// Grows faces from each triangle not yet taken, in file order, over edges to triangles whose
// normal lies within the merge angle of the face's (area-weighted) normal so far: comparing with
// the face rather than the neighbour keeps a gently curved strip from being chained into one face.
// Triangles without area join a face they touch.
std::vector<Face> mergeFaces(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, double mergeAngleDegrees,
                             double areaEpsilon, std::vector<int>& faceOf, const std::string& source) {
  const size_t n = mesh.triangles.size();
  std::vector<Vec3> doubleAreaNormal(n);
  std::vector<bool> degenerate(n);
  for (size_t t = 0; t < n; ++t) {
    const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
    doubleAreaNormal[t] = cross(minus(mesh.vertices[mesh.triangles[t][1]], a), minus(mesh.vertices[mesh.triangles[t][2]], a));
    degenerate[t] = norm(doubleAreaNormal[t]) <= areaEpsilon;
  }
  const double cosMerge = std::cos(mergeAngleDegrees * kPi / 180);
  faceOf.assign(n, -1);
  std::vector<Face> faces;
  std::vector<int> queue;
  for (size_t seed = 0; seed < n; ++seed) {
    if (faceOf[seed] >= 0 || degenerate[seed]) continue;
    if (faces.size() == kMaxFaces) {
      throw Error(ErrorCode::TooLarge, source + ": the mesh has more than " + std::to_string(kMaxFaces) + " faces (plates)");
    }
    const int f = static_cast<int>(faces.size());
    faces.emplace_back();
    Face& face = faces.back();
    queue.assign(1, static_cast<int>(seed));
    faceOf[seed] = f;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int t = queue[head];
      face.triangles.push_back(t);
      face.normalSum = plus(face.normalSum, doubleAreaNormal[t]);
      for (int k = 0; k < 3; ++k) {
        const int u = twins[t][k];
        if (faceOf[u] >= 0) continue;
        if (degenerate[u] || dot(normalized(doubleAreaNormal[u]), normalized(face.normalSum)) >= cosMerge) {
          faceOf[u] = f;
          queue.push_back(u);
        }
      }
    }
  }
  // Triangles without area that no face reached (all their neighbours without area too): give
  // them to a face they touch, pass by pass; each pass takes at least one or ends.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t t = 0; t < n; ++t) {
      if (faceOf[t] >= 0) continue;
      for (int k = 0; k < 3 && faceOf[t] < 0; ++k) {
        if (faceOf[twins[t][k]] >= 0) {
          faceOf[t] = faceOf[twins[t][k]];
          faces[faceOf[t]].triangles.push_back(static_cast<int>(t));
          changed = true;
        }
      }
    }
  }
  if (faces.empty()) throwBadInput(source, "the mesh's triangles have no area");
  for (Face& face : faces) {
    std::sort(face.triangles.begin(), face.triangles.end());
    face.plane.normal = normalized(face.normalSum);
    double area = 0;
    for (int t : face.triangles) {
      const auto& tri = mesh.triangles[t];
      const double a = norm(doubleAreaNormal[t]);
      const Vec3 centroid = scaled(plus(plus(mesh.vertices[tri[0]], mesh.vertices[tri[1]]), mesh.vertices[tri[2]]), 1.0 / 3);
      face.centre = plus(face.centre, scaled(centroid, a));
      area += a;
    }
    face.centre = scaled(face.centre, 1 / area);
  }
  return faces;
}

// The face's plane: halfway between its extreme vertices along its normal; refuses a face whose
// vertices lie further than the tolerance from it.
void fitPlane(const TriangleMesh& mesh, std::vector<Face>& faces, int f, const MitredPlateOptions& options, const std::string& source) {
  Face& face = faces[f];
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  int loVertex = 0, hiVertex = 0;
  for (int t : face.triangles) {
    for (int v : mesh.triangles[t]) {
      const double h = dot(face.plane.normal, mesh.vertices[v]);
      if (h < lo) lo = h, loVertex = v;
      if (h > hi) hi = h, hiVertex = v;
    }
  }
  face.plane.offset = (lo + hi) / 2;
  if ((hi - lo) / 2 > options.tolerance) {
    throwBadInput(source, faceLabel(faces, f) + " is not planar: its vertices lie up to " + number((hi - lo) / 2) +
                              " mm off one plane (" + vertexText(mesh, hiVertex) + " above, " + vertexText(mesh, loVertex) +
                              " below; tolerance " + number(options.tolerance) + " mm). Its triangles' normals differ by less than the merge angle (" +
                              number(options.mergeAngleDegrees) + " degrees), so they were taken as one face: flatten it in the model, or give a smaller merge angle "
                              "to make separate plates of them");
  }
}

// The face's outline: its triangles' edges to other faces, chained; vertices where the outline
// runs on along the same neighbour (a triangulation's extra points) are not corners.
void traceOutline(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, const std::vector<int>& faceOf,
                  std::vector<Face>& faces, int f, const std::string& source) {
  Face& face = faces[f];
  std::map<int, std::pair<int, int>> next;  // boundary edge by its start: (end, face across)
  for (int t : face.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int across = faceOf[twins[t][k]];
      if (across == f) continue;
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (!next.emplace(a, std::make_pair(b, across)).second) {
        throwBadInput(source, faceLabel(faces, f) + " touches itself at " + vertexText(mesh, a) +
                                  " (its outline passes there twice); plates-from-mesh needs faces with a simple outline");
      }
    }
  }
  if (next.empty()) throwBadInput(source, faceLabel(faces, f) + " has no outline: the mesh is one flat face");
  std::vector<int> loop, across;
  int at = next.begin()->first;
  for (size_t guard = 0; guard <= next.size(); ++guard) {
    loop.push_back(at);
    across.push_back(next[at].second);
    at = next[at].first;
    if (at == loop[0]) break;
  }
  if (loop.size() != next.size()) {
    throwBadInput(source, faceLabel(faces, f) + " has a hole (its outline is " + std::to_string(next.size() - loop.size() + 1) +
                              "+ separate loops); plates-from-mesh makes plates without holes: model the opening as faces "
                              "that do not lie in this face's plane, or leave it out");
  }
  const size_t n = loop.size();
  std::vector<size_t> cornerAt;
  for (size_t i = 0; i < n; ++i) {
    if (across[(i + n - 1) % n] != across[i]) cornerAt.push_back(i);
  }
  if (cornerAt.size() < 3) {
    throwBadInput(source, faceLabel(faces, f) + " has only " + std::to_string(cornerAt.size()) +
                              " corners where its neighbours change: the mesh encloses no volume there");
  }
  const auto lowest = std::min_element(cornerAt.begin(), cornerAt.end(), [&](size_t x, size_t y) { return loop[x] < loop[y]; });
  std::rotate(cornerAt.begin(), lowest, cornerAt.end());
  for (size_t i : cornerAt) {
    face.corners.push_back(loop[i]);
    face.sideFace.push_back(across[i]);
  }
}

}  // namespace

std::string faceLabel(const std::vector<Face>& faces, int f) {
  Vec3 centre = faces[f].centre;
  for (double& c : centre) c = std::round(c * 10) / 10 + 0.0;  // to 0.1 mm, no "-0"
  return "face " + std::to_string(f + 1) + " (around " + pointText(centre) + ")";
}

std::vector<Face> meshFaces(const OrientedMesh& oriented, const MitredPlateOptions& options, const std::string& source) {
  std::vector<int> faceOf;
  const TriangleMesh& mesh = oriented.mesh;
  const double size = oriented.size;
  std::vector<Face> faces = mergeFaces(mesh, oriented.twins, options.mergeAngleDegrees,
                                       tolerance::kProductRounding * size * size, faceOf, source);
  for (size_t f = 0; f < faces.size(); ++f) fitPlane(mesh, faces, static_cast<int>(f), options, source);
  for (size_t f = 0; f < faces.size(); ++f) traceOutline(mesh, oriented.twins, faceOf, faces, static_cast<int>(f), source);
  // Two faces folded flat onto each other have no mitre (their bisector is their own plane). The
  // usual cause is a reader's fan triangulation of a non-convex polygon, which turns triangles over.
  const double cosMerge = std::cos(options.mergeAngleDegrees * kPi / 180);
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t k = 0; k < faces[f].corners.size(); ++k) {
      const int g = faces[f].sideFace[k];
      if (norm(minus(faces[f].plane.normal, faces[g].plane.normal)) < tolerance::kDirection) {
        // Possible only when the merge grew two faces of a gently curved surface to equal normals.
        throwBadInput(source, faceLabel(faces, static_cast<int>(f)) + " and " + faceLabel(faces, g) +
                                  " are neighbours in one plane: they have no mitre; give a larger merge angle");
      }
      if (dot(faces[f].plane.normal, faces[g].plane.normal) <= -cosMerge) {
        throwBadInput(source, "the surface folds back onto itself between " + faceLabel(faces, static_cast<int>(f)) + " and " +
                                  faceLabel(faces, g) + " at the edge from vertex " + std::to_string(faces[f].corners[k] + 1) +
                                  " to vertex " + std::to_string(faces[f].corners[(k + 1) % faces[f].corners.size()] + 1) +
                                  ": their normals are opposite. An OBJ polygon is read as a fan of triangles from its first "
                                  "vertex, which turns triangles over in a non-convex polygon: triangulate the faces in the "
                                  "modelling tool before exporting");
      }
    }
  }
  return faces;
}

}  // namespace mitred
}  // namespace desia
