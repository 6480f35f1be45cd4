// SPDX-License-Identifier: GPL-3.0-or-later
// Mitred plates from a low-poly mesh: one plate per planar face, inset inside the mesh.
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
#include "desia/plate.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/mitred_faces.h"
#include "plate/mitred_mesh.h"

namespace desia {
namespace {

using mitred::Face;
using mitred::faceLabel;
using mitred::meshFaces;
using mitred::number;
using mitred::orientedMesh;
using mitred::OrientedMesh;
using mitred::Plane;
using mitred::pointText;
using mitred::vertexText;
using mitred::windingNumber;

constexpr double kMaxInsideTests = 2e8;  // inner corners x triangles: a few seconds of winding numbers

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

// The point on three planes, or nothing when two of them are (nearly) parallel.
bool intersectPlanes(const Plane& p, const Plane& q, const Plane& r, Vec3& point) {
  const Vec3 qr = cross(q.normal, r.normal), rp = cross(r.normal, p.normal), pq = cross(p.normal, q.normal);
  const double det = dot(p.normal, qr);
  if (std::abs(det) < tolerance::kDirection) return false;
  point = scaled(plus(plus(scaled(qr, p.offset), scaled(rp, q.offset)), scaled(pq, r.offset)), 1 / det);
  return true;
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
// blocking tests' tolerance::kDirection (README "Verdicts on computed normals"): a slide along
// such mitres pushes into the faces it runs along. From the planes, every face of a plate and every mitre is
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
// instead of a few (and the search many times the nodes). A nanometre grid makes them equal again
// and turns a face by at most 1e-11 rad on a 100 mm plate, far below the blocking tests'
// tolerance::kDirection.
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

// Throws BadInput naming the option unless the thickness, the tolerance and the merge angle are
// in range.
void requireOptions(const MitredPlateOptions& options, const std::string& source) {
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
}

// Each face's inner corners (where its inner plane meets the mitres of the corner's two sides);
// throws BadInput where the thickness is too large for the face, saying how large it may be.
std::vector<std::vector<Vec3>> innerFaces(const TriangleMesh& mesh, const std::vector<Face>& faces,
                                          const MitredPlateOptions& options, const std::string& source) {
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
  return inner;
}

// Every inner corner inside the mesh (BadInput naming it where the shape is thinner than two
// plates); TooLarge where that test would take too long.
void requireInsideTheMesh(const TriangleMesh& mesh, const std::vector<Face>& faces,
                          const std::vector<std::vector<Vec3>>& inner, const MitredPlateOptions& options,
                          const std::string& source) {
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
}

// The mesh's edges (each one mitre) and, where more than three faces meet, by how much
// neighbours' inner corners differ.
void measureCorners(const std::vector<Face>& faces, const std::vector<std::vector<Vec3>>& inner, MitredPlates& result) {
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
}

// One plate per face (its outer corners on the mesh face, its inner corners below them), checked
// as any plate is.
void addPlates(const TriangleMesh& mesh, const std::vector<Face>& faces, const std::vector<std::vector<Vec3>>& inner,
               const MitredPlateOptions& options, const std::string& source, MitredPlates& result) {
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
}

// Every mitre must have become a contact; otherwise the structure would silently lose a joint.
void requireAContactPerMitre(const std::vector<Face>& faces, const MitredPlates& result, const std::string& source) {
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
}

}  // namespace

MitredPlates mitredPlatesFromMesh(const TriangleMesh& input, const MitredPlateOptions& options, const std::string& source) {
  requireOptions(options, source);
  const OrientedMesh oriented = orientedMesh(input, source);
  const TriangleMesh& mesh = oriented.mesh;
  const std::vector<Face> faces = meshFaces(oriented, options, source);
  const std::vector<std::vector<Vec3>> inner = innerFaces(mesh, faces, options, source);
  requireInsideTheMesh(mesh, faces, inner, options, source);
  MitredPlates result;
  result.reoriented = oriented.reoriented;
  measureCorners(faces, inner, result);
  addPlates(mesh, faces, inner, options, source, result);
  result.contacts = computePlateContacts(result.plates, PlateOptions{options.tolerance});
  requireAContactPerMitre(faces, result, source);
  return result;
}

}  // namespace desia
