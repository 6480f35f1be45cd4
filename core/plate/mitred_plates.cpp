// SPDX-License-Identifier: GPL-3.0-or-later
// Mitred plates from a low-poly mesh (issue 8): one plate per planar face, inset inside the mesh.
//
// Every plane here is written n·x = c with a unit n. For a face F (outward normal n_F, plane
// n_F·x = d_F) the inner face lies on n_F·x = d_F - T. The mitre between F and its neighbour G is
// the set of points equally far from both planes on the inside, (n_F - n_G)·x = d_F - d_G; it
// contains their shared edge, and on it a point at depth T below F is at depth T below G too, so
// both plates' inner edges along the mitre lie on one line and their side faces on one plane.
// Each inner corner is where the inner plane meets the mitres of the corner's two sides. Where
// three faces meet a vertex, the three mitres share a line and every plate gets the same inner
// corner; where more meet, the corners differ (reported as largestCornerMismatch) and the mitre
// faces of two neighbours overlap in part only, which still makes a contact.
#include "desia/mitred_plates.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "analysis/vec3.h"
#include "desia/error.h"

namespace desia {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxFaces = 10000;  // the plate document's own limit
constexpr double kMaxInsideTests = 2e8;  // inner corners x triangles: a few seconds of winding numbers


std::string number(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

// An option as given, with enough digits that a value refused is not printed as the limit it
// passed (a merge angle of 30.0001 as "30").
std::string givenNumber(double value) {
  for (int digits = 4;; ++digits) {  // the fewest digits that read back as the value
    std::ostringstream out;
    out.precision(digits);
    out << value;
    if (digits >= 17 || std::strtod(out.str().c_str(), nullptr) == value) return out.str();
  }
}

std::string pointText(const Vec3& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return out.str();
}

std::string vertexText(const TriangleMesh& mesh, int v) {
  return "vertex " + std::to_string(v + 1) + " " + pointText(mesh.vertices[v]);
}

uint64_t directedKey(int a, int b) { return static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32 | static_cast<uint32_t>(b); }

struct Plane {
  Vec3 normal;  // unit
  double offset = 0;
};

// The point on three planes, or nothing when two of them are (nearly) parallel.
bool intersectPlanes(const Plane& p, const Plane& q, const Plane& r, Vec3& point) {
  const Vec3 qr = cross(q.normal, r.normal), rp = cross(r.normal, p.normal), pq = cross(p.normal, q.normal);
  const double det = dot(p.normal, qr);
  if (std::abs(det) < 1e-9) return false;
  point = scaled(plus(plus(scaled(qr, p.offset), scaled(rp, q.offset)), scaled(pq, r.offset)), 1 / det);
  return true;
}

// The mesh with exactly repeated positions welded into their first vertex (OBJ and STL exports
// may repeat a position per face), and the triangles that collapse by that dropped. Vertex numbers
// stay the file's.
TriangleMesh weldedMesh(const TriangleMesh& mesh, const std::string& source) {
  const int vertexCount = static_cast<int>(mesh.vertices.size());
  for (int v = 0; v < vertexCount; ++v) {
    for (double c : mesh.vertices[v]) {
      if (!std::isfinite(c)) throwBadInput(source, "vertex " + std::to_string(v + 1) + " has a coordinate that is not finite");
    }
  }
  TriangleMesh welded;
  welded.vertices = mesh.vertices;
  std::map<Vec3, int> firstAt;
  std::vector<int> target(mesh.vertices.size());
  for (int v = 0; v < vertexCount; ++v) target[v] = firstAt.emplace(mesh.vertices[v], v).first->second;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<int, 3> tri = mesh.triangles[t];
    for (int& v : tri) {
      if (v < 0 || v >= vertexCount) throwBadInput(source, "triangle " + std::to_string(t + 1) + " refers to a vertex that does not exist");
      v = target[v];
    }
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]) welded.triangles.push_back(tri);
  }
  return welded;
}

// twin[t][k]: the triangle on the other side of triangle t's edge k (from corner k to k+1).
std::vector<std::array<int, 3>> triangleTwins(const TriangleMesh& mesh, const std::string& source) {
  std::unordered_map<uint64_t, int> owner;
  owner.reserve(mesh.triangles.size() * 3);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      const auto [it, added] = owner.emplace(directedKey(a, b), static_cast<int>(t));
      if (!added) {
        throwBadInput(source, "the mesh is not consistently oriented: triangles " + std::to_string(it->second + 1) + " and " +
                                  std::to_string(t + 1) + " both run from " + vertexText(mesh, a) + " to " + vertexText(mesh, b) +
                                  " (one of them faces the other way; in Blender: Mesh > Normals > Recalculate Outside)");
      }
    }
  }
  std::vector<std::array<int, 3>> twins(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      // Every edge is in exactly two triangles (checked before), so the reverse edge exists.
      twins[t][k] = owner.at(directedKey(mesh.triangles[t][(k + 1) % 3], mesh.triangles[t][k]));
    }
  }
  return twins;
}

// Closed (checkClosedMesh: every edge in an even number of triangles), then manifold: every edge
// in exactly two, and the triangles around every vertex one fan.
void requireManifold(const TriangleMesh& mesh, const std::string& source) {
  checkClosedMesh(mesh, source);
  std::map<std::pair<int, int>, int> uses;  // ordered: the first bad edge named is the same everywhere
  for (const auto& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++uses[{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])}];
  }
  for (const auto& [edge, count] : uses) {
    if (count > 2) {
      throwBadInput(source, "the mesh is not manifold: the edge between " + vertexText(mesh, edge.first) + " and " +
                                vertexText(mesh, edge.second) + " belongs to " + std::to_string(count) +
                                " triangles (a closed surface has 2 at every edge; solids touching along an edge "
                                "cannot be made of mitred plates)");
    }
  }
}

void requireManifoldVertices(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, const std::string& source) {
  std::vector<std::vector<std::pair<int, int>>> around(mesh.vertices.size());  // (triangle, corner)
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) around[mesh.triangles[t][k]].push_back({static_cast<int>(t), k});
  }
  for (size_t v = 0; v < around.size(); ++v) {
    if (around[v].empty()) continue;
    // Walk the fan: leave each triangle over its edge starting at v; the next triangle has v too.
    int t = around[v][0].first, k = around[v][0].second;
    size_t steps = 0;
    do {
      const int next = twins[t][k];
      const auto& tri = mesh.triangles[next];
      k = tri[0] == static_cast<int>(v) ? 0 : (tri[1] == static_cast<int>(v) ? 1 : 2);
      t = next;
      ++steps;
    } while (t != around[v][0].first && steps <= around[v].size());
    if (steps != around[v].size()) {
      throwBadInput(source, "the mesh is not manifold: the surface touches itself at " + vertexText(mesh, static_cast<int>(v)) +
                                " (" + std::to_string(around[v].size()) + " triangles there, in separate fans)");
    }
  }
}

void requireOnePiece(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, const std::string& source) {
  std::vector<int> parent(mesh.triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t t = 0; t < twins.size(); ++t) {
    for (int k = 0; k < 3; ++k) parent[find(twins[t][k])] = find(static_cast<int>(t));
  }
  int pieces = 0;
  for (size_t t = 0; t < parent.size(); ++t) pieces += find(static_cast<int>(t)) == static_cast<int>(t);
  if (pieces > 1) {
    throwBadInput(source, "the mesh has " + std::to_string(pieces) +
                              " separate closed pieces; plates-from-mesh makes one structure from one closed surface "
                              "(the pieces' plates would not touch)");
  }
}

// A planar face of the mesh: triangles merged across edges where their normals agree.
struct Face {
  std::vector<int> triangles;
  Vec3 normalSum{0, 0, 0};  // area-weighted (twice the area)
  Plane plane;              // outward unit normal; the offset halfway between the extreme vertices
  Vec3 centre{0, 0, 0};     // area-weighted centroid, for messages
  std::vector<int> corners;     // mesh vertices, counter-clockwise from outside, lowest index first
  std::vector<int> sideFace;    // the face across side k (corner k to k+1)
};

std::string faceLabel(const std::vector<Face>& faces, int f) {
  Vec3 centre = faces[f].centre;
  for (double& c : centre) c = std::round(c * 10) / 10 + 0.0;  // to 0.1 mm, no "-0"
  return "face " + std::to_string(f + 1) + " (around " + pointText(centre) + ")";
}

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

// The mitre plane between face f and face g (see the file comment).
Plane mitre(const std::vector<Face>& faces, int f, int g) {
  const Vec3 normal = minus(faces[f].plane.normal, faces[g].plane.normal);
  const double length = norm(normal);
  return {scaled(normal, 1 / length), (faces[f].plane.offset - faces[g].plane.offset) / length};
}

// Inner corners of face f for thickness t; false with the corner index when two planes are parallel.
bool innerCorners(const std::vector<Face>& faces, int f, double t, std::vector<Vec3>& inner, size_t& badCorner) {
  const Face& face = faces[f];
  const size_t n = face.corners.size();
  const Plane innerPlane{face.plane.normal, face.plane.offset - t};
  inner.assign(n, Vec3{0, 0, 0});
  for (size_t k = 0; k < n; ++k) {
    if (!intersectPlanes(innerPlane, mitre(faces, f, face.sideFace[(k + n - 1) % n]), mitre(faces, f, face.sideFace[k]), inner[k])) {
      badCorner = k;
      return false;
    }
  }
  return true;
}

// The outer corners of face f: where its plane meets the mitres of the corner's two sides (its
// inner corners at depth 0), not the mesh's vertices. A mesh written to a micrometre (an OBJ's 6
// decimals, as Blender writes them) has faces that are planar to 1e-7 mm only: plates with those
// vertices have faces whose normals, and mitres whose planes, disagree by 1e-9 rad, past the
// blocking tests' 1e-9 (README "Verdicts on computed normals"); a slide along the LIZARD's mitres
// pushed into the faces it runs along. From the planes, every face of a plate and every mitre is
// planar to the rounding of doubles, and two plates' outer edges along a mitre lie on one line.
// A corner the planes put further than the tolerance from its vertex (planes that meet at a
// glancing angle there) keeps the vertex.
Loop outerCorners(const TriangleMesh& mesh, const std::vector<Face>& faces, int f, double tolerance) {
  const Face& face = faces[f];
  std::vector<Vec3> fromPlanes;
  size_t badCorner = 0;
  const bool met = innerCorners(faces, f, 0, fromPlanes, badCorner);
  Loop outer;
  for (size_t k = 0; k < face.corners.size(); ++k) {
    const Vec3& vertex = mesh.vertices[face.corners[k]];
    outer.push_back(met && norm(minus(fromPlanes[k], vertex)) <= tolerance ? fromPlanes[k] : vertex);
  }
  return outer;
}

// Corners computed from planes carry the rounding of doubles (1e-14 mm): a symmetric shape's
// equal coordinates come out unequal and its zeros as 1e-14, so that its normals, equal by
// symmetry, differ in their last digits and the blocking graphs get thousands of base directions
// instead of a few (the DODECAHEDRON's milled design took 269 nodes instead of 11). A nanometre
// grid makes them equal again and turns a face by at most 1e-11 rad on a 100 mm plate, far below
// the blocking tests' 1e-9.
Loop onNanometreGrid(Loop loop) {
  for (Vec3& point : loop) {
    for (double& c : point) c = std::round(c * 1e9) / 1e9 + 0.0;  // + 0.0: no "-0"
  }
  return loop;
}

// What is wrong with an inner face (empty when nothing): a side that shrank to less than the
// tolerance or turned over, or two sides that cross. Everything in the face's plane.
std::string innerFaceProblem(const TriangleMesh& mesh, const Face& face, const std::vector<Vec3>& inner, double tolerance) {
  const size_t n = inner.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec3 outerSide = minus(mesh.vertices[face.corners[(k + 1) % n]], mesh.vertices[face.corners[k]]);
    const double along = dot(minus(inner[(k + 1) % n], inner[k]), normalized(outerSide));
    if (along < tolerance) {
      return "its inner face would lose the side along the edge from vertex " + std::to_string(face.corners[k] + 1) + " to vertex " +
             std::to_string(face.corners[(k + 1) % n] + 1);
    }
  }
  const Vec3 axis = std::abs(face.plane.normal[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(face.plane.normal, axis)), v = cross(face.plane.normal, u);
  std::vector<std::array<double, 2>> p;
  for (const Vec3& q : inner) p.push_back({dot(q, u), dot(q, v)});
  auto orient = [&](size_t a, size_t b, size_t c) {
    const double value = (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
    return value > 0 ? 1 : (value < 0 ? -1 : 0);
  };
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const size_t i2 = (i + 1) % n, j2 = (j + 1) % n;
      if (i2 == j || j2 == i) continue;  // neighbouring sides share a corner
      if (orient(i, i2, j) * orient(i, i2, j2) <= 0 && orient(j, j2, i) * orient(j, j2, i2) <= 0) {
        return "its inner face would cross itself (the sides below the edges from vertex " + std::to_string(face.corners[i] + 1) +
               " and from vertex " + std::to_string(face.corners[j] + 1) + ")";
      }
    }
  }
  return "";
}

// The largest thickness below `thickness` for which face f's inner face is sound (bisection: the
// inner corners move linearly with the thickness, and a sound face at t is sound below t).
double largestThickness(const TriangleMesh& mesh, const std::vector<Face>& faces, int f, double thickness, double tolerance) {
  double good = 0, bad = thickness;
  std::vector<Vec3> inner;
  size_t corner = 0;
  for (int step = 0; step < 50; ++step) {
    const double t = (good + bad) / 2;
    const bool sound = innerCorners(faces, f, t, inner, corner) && innerFaceProblem(mesh, faces[f], inner, tolerance).empty();
    (sound ? good : bad) = t;
  }
  return good;
}

// How many times the closed surface winds around `point` (1 inside, 0 outside): the triangles'
// solid angles (Van Oosterom and Strackee) over 4 pi.
double windingNumber(const TriangleMesh& mesh, const Vec3& point) {
  double total = 0;
  for (const auto& tri : mesh.triangles) {
    const Vec3 a = minus(mesh.vertices[tri[0]], point), b = minus(mesh.vertices[tri[1]], point), c = minus(mesh.vertices[tri[2]], point);
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * kPi);
}

}  // namespace

MitredPlates mitredPlatesFromMesh(const TriangleMesh& input, const MitredPlateOptions& options, const std::string& source) {
  if (!(options.thickness > 0) || !std::isfinite(options.thickness)) {
    throwBadInput(source, "the thickness must be a positive number of millimetres, found " + givenNumber(options.thickness));
  }
  if (!(options.tolerance > 0) || !(options.tolerance <= 10)) {
    throwBadInput(source, "the tolerance must be a positive number of millimetres up to 10, found " + givenNumber(options.tolerance));
  }
  if (!(options.thickness > options.tolerance)) {
    throwBadInput(source, "the thickness (" + givenNumber(options.thickness) + " mm) must be more than the tolerance (" +
                              givenNumber(options.tolerance) + " mm): give a larger thickness");
  }
  if (!(options.mergeAngleDegrees > 0) || !(options.mergeAngleDegrees <= 30)) {
    throwBadInput(source, "the merge angle must be more than 0 and at most 30 degrees, found " + givenNumber(options.mergeAngleDegrees));
  }
  TriangleMesh mesh = weldedMesh(input, source);
  requireManifold(mesh, source);
  std::vector<std::array<int, 3>> twins = triangleTwins(mesh, source);
  requireManifoldVertices(mesh, twins, source);
  requireOnePiece(mesh, twins, source);

  MitredPlates result;
  // Outward or inside out: the sign of the enclosed volume (about the bounding box's centre, for
  // precision far from the origin).
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& tri : mesh.triangles) {
    for (int v : tri) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], mesh.vertices[v][k]), hi[k] = std::max(hi[k], mesh.vertices[v][k]);
    }
  }
  const Vec3 middle = scaled(plus(lo, hi), 0.5);
  const double size = norm(minus(hi, lo));
  double volume = 0;
  for (const auto& tri : mesh.triangles) {
    volume += dot(minus(mesh.vertices[tri[0]], middle), cross(minus(mesh.vertices[tri[1]], middle), minus(mesh.vertices[tri[2]], middle))) / 6;
  }
  if (!(std::abs(volume) > 1e-9 * size * size * size)) throwBadInput(source, "the mesh encloses no volume");
  if (volume < 0) {
    for (auto& tri : mesh.triangles) std::swap(tri[1], tri[2]);
    twins = triangleTwins(mesh, source);
    result.reoriented = true;
  }

  std::vector<int> faceOf;
  std::vector<Face> faces = mergeFaces(mesh, twins, options.mergeAngleDegrees, 1e-12 * size * size, faceOf, source);
  for (size_t f = 0; f < faces.size(); ++f) fitPlane(mesh, faces, static_cast<int>(f), options, source);
  for (size_t f = 0; f < faces.size(); ++f) traceOutline(mesh, twins, faceOf, faces, static_cast<int>(f), source);
  // Two faces folded flat onto each other have no mitre (their bisector is their own plane). The
  // usual cause is a reader's fan triangulation of a non-convex polygon, which turns triangles over.
  const double cosMerge = std::cos(options.mergeAngleDegrees * kPi / 180);
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t k = 0; k < faces[f].corners.size(); ++k) {
      const int g = faces[f].sideFace[k];
      if (norm(minus(faces[f].plane.normal, faces[g].plane.normal)) < 1e-9) {
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

  std::vector<std::vector<Vec3>> inner(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    const int fi = static_cast<int>(f);
    size_t corner = 0;
    if (!innerCorners(faces, fi, options.thickness, inner[f], corner)) {
      throwBadInput(source, faceLabel(faces, fi) + ": the mitres at its corner at " + vertexText(mesh, faces[f].corners[corner]) +
                                " are parallel (a neighbour there folds back onto it)");
    }
    const std::string problem = innerFaceProblem(mesh, faces[f], inner[f], options.tolerance);
    if (!problem.empty()) {
      const double largest = largestThickness(mesh, faces, fi, options.thickness, options.tolerance);
      throwBadInput(source, "the thickness " + number(options.thickness) + " mm is too large for " + faceLabel(faces, fi) + ": " +
                                problem + "; this face allows at most about " + number(std::floor(largest * 100) / 100) +
                                " mm: give a smaller thickness");
    }
  }
  // A face can be sound on its own while the shape is thinner than two plates elsewhere (a dish
  // whose floor is thinner than a plate): its inner corners come out through the other side. The
  // winding number visits every triangle per corner, so the work is bounded first.
  size_t cornerCount = 0;
  for (const Face& face : faces) cornerCount += face.corners.size();
  if (static_cast<double>(cornerCount) * static_cast<double>(mesh.triangles.size()) > kMaxInsideTests) {
    throw Error(ErrorCode::TooLarge, source + ": the mesh is too large for plates-from-mesh (" + std::to_string(faces.size()) +
                                         " faces from " + std::to_string(mesh.triangles.size()) +
                                         " triangles); it is made for low-poly meshes of up to a few thousand faces");
  }
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t k = 0; k < inner[f].size(); ++k) {
      if (windingNumber(mesh, inner[f][k]) < 0.5) {
        throwBadInput(source, "the thickness " + number(options.thickness) + " mm is too large for the shape: the inner corner of " +
                                  faceLabel(faces, static_cast<int>(f)) + " below " + vertexText(mesh, faces[f].corners[k]) +
                                  " lies outside the mesh at " + pointText(inner[f][k]) +
                                  " (the shape is thinner than two plates there): give a smaller thickness");
      }
    }
  }

  // Where more than three faces meet, neighbours' inner corners differ: measure by how much.
  std::map<std::pair<int, int>, size_t> cornerIndex;  // (face, vertex) -> corner
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t k = 0; k < faces[f].corners.size(); ++k) cornerIndex[{static_cast<int>(f), faces[f].corners[k]}] = k;
  }
  int sides = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const Face& face = faces[f];
    sides += static_cast<int>(face.corners.size());
    for (size_t k = 0; k < face.corners.size(); ++k) {
      const int g = face.sideFace[k];
      for (const size_t end : {k, (k + 1) % face.corners.size()}) {
        const auto there = cornerIndex.find({g, face.corners[end]});
        if (there == cornerIndex.end()) continue;
        result.largestCornerMismatch = std::max(result.largestCornerMismatch, norm(minus(inner[f][end], inner[g][there->second])));
      }
    }
  }
  result.meshEdges = sides / 2;

  for (size_t f = 0; f < faces.size(); ++f) {
    Plate plate;
    plate.id = static_cast<int>(f) + 1;
    plate.bottom.push_back(onNanometreGrid(outerCorners(mesh, faces, static_cast<int>(f), options.tolerance)));
    plate.top.push_back(onNanometreGrid(inner[f]));
    result.plates.push_back(plate);
    result.sideNeighbours.push_back(faces[f].sideFace);
    result.cornerVertices.push_back(faces[f].corners);
    result.faceTriangles.push_back(faces[f].triangles);
  }
  const PlateOptions plateOptions{options.tolerance};
  try {
    validatePlates(result.plates, plateOptions, "");
  } catch (const Error& error) {
    // The plates are built here, not given: say what in the mesh they come from.
    if (error.code() != ErrorCode::BadInput) throw;
    throwBadInput(source, std::string("the plates built for the mesh's faces (plate k for face k) do not hold together: ") +
                              error.what() + "; the faces meeting there do not make one shape at a thickness of " +
                              number(options.thickness) + " mm: give a smaller thickness or flatten the mesh there");
  }
  result.contacts = computePlateContacts(result.plates, plateOptions);
  // Every mitre must have become a contact; otherwise the structure would silently lose a joint.
  std::map<std::pair<int, int>, int> contactsOfPair, sidesOfPair;
  for (const PlateContact& c : result.contacts) ++contactsOfPair[{std::min(c.a, c.b), std::max(c.a, c.b)}];
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int g : faces[f].sideFace) {
      if (static_cast<int>(f) < g) ++sidesOfPair[{static_cast<int>(f), g}];
    }
  }
  for (const auto& [pair, count] : sidesOfPair) {
    if (contactsOfPair[pair] < count) {
      throwBadInput(source, faceLabel(faces, pair.first) + " and " + faceLabel(faces, pair.second) +
                                " share an edge, but their mitre faces do not touch over an area larger than the tolerance "
                                "(a very short edge, or corners where more than three faces meet that disagree by up to " +
                                number(result.largestCornerMismatch) + " mm): give a smaller thickness");
    }
  }
  return result;
}

}  // namespace desia
