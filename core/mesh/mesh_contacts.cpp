// SPDX-License-Identifier: GPL-3.0-or-later
// Contacts of a mesh assembly (paper Section 3.1, as plates find theirs): the planar faces of each
// part (edge-connected triangles facing one way, on one plane within the tolerance), and a contact
// wherever a face of one part lies on a face of another with opposite normals and their overlap,
// a 2D polygon intersection by Clipper in the first face's plane, has positive area. A curved
// region is a set of small faces: its contacts are those of its facets, and it is named as a
// curved contact (the note that such contacts are approximated).
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <deque>

#include "desia/tolerances.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {
namespace {

// Clipper's integers: the model's bounding-box diagonal spans this many steps, whatever its unit
// or size (far below the tolerance, kMeshContactShare, and far from Clipper's 64-bit range).
constexpr double kClipperStepsPerDiagonal = 1e9;
// A curved contact region has at least this many facets (two faces at a slight angle are a bend).
constexpr int kLeastCurvedFacets = 3;

struct Face {
  int part = 0;
  Vec3 normal{0, 0, 0};  // unit, outward (area-weighted over its triangles)
  Vec3 point{0, 0, 0};   // on its plane
  std::vector<int> triangles;
  Box box;
};

// Triangle adjacency through shared undirected edges (an edge of four triangles, where a part
// touches itself, joins all four; region growing below still asks for one plane).
std::vector<std::vector<int>> neighbours(const TriangleMesh& mesh) {
  struct EdgeUse {
    int low, high, triangle;
    bool operator<(const EdgeUse& o) const {
      return std::tie(low, high, triangle) < std::tie(o.low, o.high, o.triangle);
    }
  };
  std::vector<EdgeUse> uses;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][static_cast<size_t>(k)], b = mesh.triangles[t][static_cast<size_t>((k + 1) % 3)];
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t)});
    }
  }
  std::sort(uses.begin(), uses.end());
  std::vector<std::vector<int>> result(mesh.triangles.size());
  for (size_t k = 0; k < uses.size();) {
    size_t end = k + 1;
    while (end < uses.size() && uses[end].low == uses[k].low && uses[end].high == uses[k].high) ++end;
    for (size_t i = k; i < end; ++i) {
      for (size_t j = k; j < end; ++j) {
        if (i != j) result[static_cast<size_t>(uses[i].triangle)].push_back(uses[j].triangle);
      }
    }
    k = end;
  }
  return result;
}

// A part's planar faces, the face of each triangle (-1 for one of no area) and the triangles'
// neighbours (for faces that share an edge: curved regions).
struct PartFaces {
  std::vector<Face> faces;
  std::vector<int> faceOf;
  std::vector<std::vector<int>> adjacent;
};

// Planar faces by region growing from each unassigned triangle in index order: a neighbour joins
// when it faces the seed's way (tolerance::kFacingCosine) and its corners lie within the tolerance
// of the seed's plane.
PartFaces planarFaces(int part, const TriangleMesh& mesh, const std::vector<Triangle>& triangles, double tolerance) {
  PartFaces result{{}, std::vector<int>(triangles.size(), -1), neighbours(mesh)};
  const std::vector<std::vector<int>>& adjacent = result.adjacent;
  std::vector<int>& faceOf = result.faceOf;
  std::vector<Face>& faces = result.faces;
  for (size_t seed = 0; seed < triangles.size(); ++seed) {
    if (faceOf[seed] >= 0 || triangles[seed].twiceArea == 0) continue;
    Face face;
    face.part = part;
    const Vec3 n = triangles[seed].normal;
    const double offset = dot(n, triangles[seed].p[0]);
    std::deque<int> queue{static_cast<int>(seed)};
    faceOf[seed] = static_cast<int>(faces.size());
    Vec3 weighted{0, 0, 0};
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop_front();
      face.triangles.push_back(t);
      const Triangle& triangle = triangles[static_cast<size_t>(t)];
      weighted = plus(weighted, scaled(triangle.normal, triangle.twiceArea));
      for (const Vec3& p : triangle.p) face.box.add(p);
      for (int next : adjacent[static_cast<size_t>(t)]) {
        const Triangle& other = triangles[static_cast<size_t>(next)];
        if (faceOf[static_cast<size_t>(next)] >= 0 || other.twiceArea == 0) continue;
        if (dot(other.normal, n) < 1 - tolerance::kFacingCosine) continue;
        bool onPlane = true;
        for (const Vec3& p : other.p) onPlane = onPlane && std::abs(dot(n, p) - offset) <= tolerance;
        if (!onPlane) continue;
        faceOf[static_cast<size_t>(next)] = static_cast<int>(faces.size());
        queue.push_back(next);
      }
    }
    face.normal = normalized(weighted);
    face.point = triangles[seed].p[0];
    faces.push_back(std::move(face));
  }
  return result;
}

// A plane's 2D frame and Clipper's integer coordinates in it.
struct FlatFrame {
  Vec3 origin, u, v;
  double scale;
  FlatFrame(const Vec3& origin_, const Vec3& normal, double scale_) : origin(origin_), scale(scale_) {
    const Vec3 axis = std::abs(normal[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u = normalized(cross(normal, axis));
    v = cross(normal, u);
  }
  ClipperLib::IntPoint flat(const Vec3& p) const {
    const Vec3 d = minus(p, origin);
    return {static_cast<ClipperLib::cInt>(std::llround(dot(d, u) * scale)),
            static_cast<ClipperLib::cInt>(std::llround(dot(d, v) * scale))};
  }
};

ClipperLib::Paths flatTriangles(const Face& face, const std::vector<Triangle>& triangles, const FlatFrame& frame) {
  ClipperLib::Paths paths;
  for (int t : face.triangles) {
    ClipperLib::Path path;
    for (const Vec3& p : triangles[static_cast<size_t>(t)].p) path.push_back(frame.flat(p));
    paths.push_back(path);
  }
  return paths;
}

// The overlap of two faces on one plane, in mm², and the diagonal of its bounding box (triangles of one face never overlap each other,
// so the non-zero rule unites them whichever way each is turned in the frame).
double overlapArea(const Face& f, const Face& g, const std::vector<PartGeometry>& geometry, double scale,
                   double* extent) {
  const FlatFrame frame(f.point, f.normal, scale);
  ClipperLib::Clipper clipper;
  clipper.AddPaths(flatTriangles(f, geometry[static_cast<size_t>(f.part)].triangles, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(flatTriangles(g, geometry[static_cast<size_t>(g.part)].triangles, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths overlap;
  clipper.Execute(ClipperLib::ctIntersection, overlap, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  ClipperLib::cInt lo[2] = {0, 0}, hi[2] = {0, 0};
  bool first = true;
  for (const ClipperLib::Path& path : overlap) {
    area += ClipperLib::Area(path);
    for (const ClipperLib::IntPoint& p : path) {
      lo[0] = first ? p.X : std::min(lo[0], p.X), hi[0] = first ? p.X : std::max(hi[0], p.X);
      lo[1] = first ? p.Y : std::min(lo[1], p.Y), hi[1] = first ? p.Y : std::max(hi[1], p.Y);
      first = false;
    }
  }
  *extent = std::hypot(static_cast<double>(hi[0] - lo[0]), static_cast<double>(hi[1] - lo[1])) / scale;
  return std::abs(area) / (scale * scale);
}

// Faces whose boxes share only a thin tube (thinner than half the tolerance across two axes) meet at
// most along an edge: their overlap would be a sliver, no contact (the faces of parts that touch
// along an edge or at a corner, most candidate pairs of a grid of parts).
bool meetOnlyAlongALine(const Box& a, const Box& b, double tolerance) {
  int thin = 0;
  for (int i = 0; i < 3; ++i) {
    if (std::min(a.hi[i], b.hi[i]) - std::max(a.lo[i], b.lo[i]) <= tolerance / 2) ++thin;
  }
  return thin >= 2;
}

bool onOneAnother(const Face& f, const Face& g, const std::vector<PartGeometry>& geometry, double tolerance) {
  if (dot(f.normal, g.normal) > -(1 - tolerance::kFacingCosine)) return false;
  if (!f.box.overlaps(g.box, tolerance) || meetOnlyAlongALine(f.box, g.box, tolerance)) return false;
  const double offset = dot(f.normal, f.point);
  for (int t : g.triangles) {
    for (const Vec3& p : geometry[static_cast<size_t>(g.part)].triangles[static_cast<size_t>(t)].p) {
      if (std::abs(dot(f.normal, p) - offset) > tolerance) return false;
    }
  }
  return true;
}

// Normals meant to be one (a rotated or rescaled model, floats of a binary STL) are made one: each
// takes the first earlier normal within tolerance::kDrawnDirectionRad of it or of its opposite (a
// file written to 6 decimals turns a face by up to some 1e-5 rad).
void unifyNormals(std::vector<Contact>* contacts) {
  std::vector<Vec3> seen;
  for (Contact& contact : *contacts) {
    bool matched = false;
    for (const Vec3& s : seen) {
      if (norm(cross(s, contact.normal)) <= tolerance::kDrawnDirectionRad) {
        contact.normal = dot(s, contact.normal) > 0 ? s : negated(s);
        matched = true;
        break;
      }
    }
    if (!matched) {
      if (const auto cleaned = cleanedNormal(contact.normal)) contact.normal = *cleaned;
      seen.push_back(contact.normal);
    }
  }
}

// A contact and the face of its first part it came from.
struct FaceContact {
  size_t contact;
  int face;
};

// Curved contact regions of part a against part b: the faces of a in contact with b, joined where
// two share an edge at an angle below kCurvedFacetRad; a group of kLeastCurvedFacets or more is
// one curved region (a pin in a hole, a ball in a socket), its contacts those of its facets.
void addCurvedRegions(size_t a, size_t b, const PartFaces& faces, const std::vector<FaceContact>& touching,
                      const std::vector<Contact>& contacts, std::vector<CurvedContact>* curved) {
  std::vector<double> area(faces.faces.size(), 0);
  std::vector<bool> inContact(faces.faces.size(), false), seen(faces.faces.size(), false);
  for (const FaceContact& c : touching) {
    inContact[static_cast<size_t>(c.face)] = true;
    area[static_cast<size_t>(c.face)] += contacts[c.contact].area;
  }
  const double leastCosine = std::cos(tolerance::kCurvedFacetRad);
  for (const FaceContact& start : touching) {
    if (seen[static_cast<size_t>(start.face)]) continue;
    seen[static_cast<size_t>(start.face)] = true;
    std::vector<int> stack{start.face};
    CurvedContact region{static_cast<int>(a), static_cast<int>(b), 0, 0};
    while (!stack.empty()) {
      const int face = stack.back();
      stack.pop_back();
      ++region.facets;
      region.area += area[static_cast<size_t>(face)];
      for (int t : faces.faces[static_cast<size_t>(face)].triangles) {
        for (int next : faces.adjacent[static_cast<size_t>(t)]) {
          const int other = faces.faceOf[static_cast<size_t>(next)];
          if (other < 0 || !inContact[static_cast<size_t>(other)] || seen[static_cast<size_t>(other)]) continue;
          if (dot(faces.faces[static_cast<size_t>(face)].normal, faces.faces[static_cast<size_t>(other)].normal) < leastCosine) {
            continue;
          }
          seen[static_cast<size_t>(other)] = true;
          stack.push_back(other);
        }
      }
    }
    if (region.facets >= kLeastCurvedFacets) curved->push_back(region);
  }
}

}  // namespace

std::vector<Contact> meshContacts(const std::vector<MeshPart>& parts, const std::vector<PartGeometry>& geometry,
                                  double tolerance, double emptyArea, int* faceCount,
                                  std::vector<CurvedContact>* curved) {
  Box all;
  for (const PartGeometry& g : geometry) all.add(g.box);
  const double diagonal = norm(minus(all.hi, all.lo));
  const double scale = kClipperStepsPerDiagonal / diagonal;
  std::vector<PartFaces> faces;
  *faceCount = 0;
  for (size_t p = 0; p < parts.size(); ++p) {
    faces.push_back(planarFaces(static_cast<int>(p), parts[p].mesh, geometry[p].triangles, tolerance));
    *faceCount += static_cast<int>(faces.back().faces.size());
  }
  std::vector<Contact> contacts;
  curved->clear();
  for (size_t a = 0; a < parts.size(); ++a) {
    for (size_t b = a + 1; b < parts.size(); ++b) {
      if (!geometry[a].box.overlaps(geometry[b].box, tolerance)) continue;
      std::vector<FaceContact> touching;
      for (size_t fi = 0; fi < faces[a].faces.size(); ++fi) {
        const Face& f = faces[a].faces[fi];
        if (!f.box.overlaps(geometry[b].box, tolerance)) continue;
        for (const Face& g : faces[b].faces) {
          if (!onOneAnother(f, g, geometry, tolerance)) continue;
          double extent = 0;
          const double area = overlapArea(f, g, geometry, scale, &extent);
          if (area <= std::max(emptyArea, tolerance * extent)) continue;  // none, or a sliver along an edge
          touching.push_back({contacts.size(), static_cast<int>(fi)});
          contacts.push_back({static_cast<int>(a), static_cast<int>(b), normalized(minus(f.normal, g.normal)), area});
        }
      }
      addCurvedRegions(a, b, faces[a], touching, contacts, curved);
    }
  }
  unifyNormals(&contacts);
  return contacts;
}

}  // namespace desia::mesh
