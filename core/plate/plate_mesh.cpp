// SPDX-License-Identifier: GPL-3.0-or-later
// A plate as a closed triangle mesh: its two faces (outline with holes) triangulated
// (face_triangulation.cpp), and one quad (two triangles) per side.
#include "desia/plate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/face_triangulation.h"
#include "plate/mesh_edges.h"
#include "plate/plane_frame.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

// A plate without attached solids: its prism, faces and sides on shared vertices, so each edge is
// used by exactly two triangles.
TriangleMesh prismMesh(const Plate& plate, double flat) {
  const Vec3 axis = plateThicknessAxis(plate);
  TriangleMesh mesh;
  // Shared vertices: every bottom loop, then every top loop, so the faces and sides meet on
  // common vertices and each edge is used by exactly two triangles.
  std::vector<int> bottomStart, topStart;
  for (const auto* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      (face == &plate.bottom ? bottomStart : topStart).push_back(static_cast<int>(mesh.vertices.size()));
      mesh.vertices.insert(mesh.vertices.end(), loop.begin(), loop.end());
    }
  }
  addFaceTriangles(plate.bottom, negated(axis), bottomStart[0], &mesh, flat);
  addFaceTriangles(plate.top, axis, topStart[0], &mesh, flat);
  // Sides: the quad between bottom edge k and top edge k, wound so that its normal is the side's
  // outward normal.
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& b = plate.bottom[l];
    const Loop& t = plate.top[l];
    const std::vector<Vec3> outward = plateSideNormals(plate, l);
    for (size_t k = 0; k < b.size(); ++k) {
      const size_t next = (k + 1) % b.size();
      const int b0 = bottomStart[l] + static_cast<int>(k), b1 = bottomStart[l] + static_cast<int>(next);
      const int t0 = topStart[l] + static_cast<int>(k), t1 = topStart[l] + static_cast<int>(next);
      const Vec3 n = cross(minus(b[next], b[k]), minus(t[k], b[k]));
      if (dot(n, outward[k]) > 0) {
        mesh.triangles.push_back({b0, b1, t1});
        mesh.triangles.push_back({b0, t1, t0});
      } else {
        mesh.triangles.push_back({b0, t1, b1});
        mesh.triangles.push_back({b0, t0, t1});
      }
    }
  }
  return mesh;
}

// --- A plate with attached solids, as one solid -------------------------------------------------
//
// The plate's prism and its attached solids (milled joints) touch but never overlap (plate.h), so
// their union is bounded by their faces less the regions where two solids touch. Those regions
// are coplanar: on every plane that holds faces, the union's surface facing +n is (the faces facing
// +n) minus (the faces facing -n) and the other way round, computed with Clipper in the plane's 2D
// frame, and faces facing the same way merge (a tenon flush with the plate's side makes one side).
// No face is cut at a slant, so this is exact up to Clipper's grid (1e-4 mm), on which the
// vertices are snapped back to the solids' own. Each merged face is then given every vertex of
// the other faces that lies on its edges (no T-junctions) and triangulated, so every edge of the
// mesh belongs to exactly two triangles.

struct PlaneFaces {
  Vec3 normal;  // the first face's outward normal; faces on the plane face it or its opposite
  Vec3 origin;
  std::vector<const geometry::SolidFace*> along, against;
};

// A welded vertex list: points within kMeshWeldMm are one vertex (the first one seen).
class VertexWelder {
 public:
  int add(const Vec3& p) {
    // Sorted by x: only points within the tolerance in x need comparing.
    auto it = byX_.lower_bound(p[0] - tolerance::kMeshWeldMm);
    for (; it != byX_.end() && it->first <= p[0] + tolerance::kMeshWeldMm; ++it) {
      const Vec3& q = points_[static_cast<size_t>(it->second)];
      if (std::abs(q[1] - p[1]) <= tolerance::kMeshWeldMm && std::abs(q[2] - p[2]) <= tolerance::kMeshWeldMm)
        return it->second;
    }
    const int index = static_cast<int>(points_.size());
    points_.push_back(p);
    byX_.emplace(p[0], index);
    return index;
  }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  std::vector<Vec3> points_;
  std::multimap<double, int> byX_;
};

double loopArea(const Loop& loop) { return norm(loopNormal(loop)) / 2; }

// The faces of the union on one plane, as loops of welded vertex indices (outline first, then
// its holes), each with its outward normal.
struct MergedFace {
  std::vector<std::vector<int>> loops;
  Vec3 normal;
};

void addRegions(const PlaneFaces& plane, bool alongNormal, VertexWelder& welder, const std::map<std::pair<ClipperLib::cInt, ClipperLib::cInt>, int>& known,
                bool pinches, std::vector<MergedFace>* faces) {
  const PlaneFrame frame(plane.origin, alongNormal ? plane.normal : negated(plane.normal));
  auto regionOf = [&](const std::vector<const geometry::SolidFace*>& list) {
    ClipperLib::Paths all;
    for (const geometry::SolidFace* face : list) {
      ClipperLib::Clipper one;
      one.AddPaths(clipperPaths(face->loops, frame), ClipperLib::ptSubject, true);
      ClipperLib::Paths region;
      one.Execute(ClipperLib::ctUnion, region, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
      all.insert(all.end(), region.begin(), region.end());
    }
    return all;
  };
  const ClipperLib::Paths subject = regionOf(alongNormal ? plane.along : plane.against);
  const ClipperLib::Paths clip = regionOf(alongNormal ? plane.against : plane.along);
  if (subject.empty()) return;
  ClipperLib::Clipper clipper;
  clipper.AddPaths(subject, ClipperLib::ptSubject, true);
  if (!clip.empty()) clipper.AddPaths(clip, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const Vec3 outward = frame.normal;
  auto vertexOf = [&](const ClipperLib::IntPoint& p) {
    // A point of the solids' own (the same grid point) keeps its position; a new one (where a
    // face's edge crosses another's) is put back on the plane.
    const auto found = known.find({p.X, p.Y});
    if (found != known.end()) return found->second;
    return welder.add(frame.fromClipper(p));
  };
  auto indices = [&](const ClipperLib::Path& path) {
    std::vector<int> loop;
    for (const ClipperLib::IntPoint& p : path) {
      const int v = vertexOf(p);
      // Where Clipper's contour touches itself (the 3D union's polygons meet at a vertex), the
      // vertex is visited twice: kept (pinches); the faces per plane drop it, as they always did.
      if (loop.empty() || (loop.back() != v && (pinches || loop.front() != v))) loop.push_back(v);
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    return loop;
  };
  // Outlines and their holes, without recursion: an explicit list of outline nodes.
  std::vector<const ClipperLib::PolyNode*> outlines;
  for (const ClipperLib::PolyNode* child : tree.Childs) outlines.push_back(child);
  for (size_t i = 0; i < outlines.size(); ++i) {
    for (const ClipperLib::PolyNode* hole : outlines[i]->Childs) {
      for (const ClipperLib::PolyNode* island : hole->Childs) outlines.push_back(island);
    }
  }
  for (const ClipperLib::PolyNode* node : outlines) {
    const double area = std::abs(ClipperLib::Area(node->Contour)) / (kClipperScale * kClipperScale);
    MergedFace face;
    face.normal = outward;
    face.loops.push_back(indices(node->Contour));
    for (const ClipperLib::PolyNode* hole : node->Childs) face.loops.push_back(indices(hole->Contour));
    // A sliver left by rounding where faces meet is no face.
    if (area < tolerance::kEmptyAreaMm2 || face.loops[0].size() < 3) continue;
    std::vector<std::vector<int>> kept{face.loops[0]};
    for (size_t h = 1; h < face.loops.size(); ++h) {
      if (face.loops[h].size() >= 3) kept.push_back(face.loops[h]);
    }
    face.loops = kept;
    faces->push_back(face);
  }
}

// Every vertex of a face that lies on an edge of a loop (strictly between its ends) inserted
// there, in order.
void insertVerticesOnEdges(std::vector<MergedFace>& faces, const std::vector<Vec3>& points) {
  std::vector<bool> used(points.size(), false);
  for (const MergedFace& face : faces) {
    for (const std::vector<int>& loop : face.loops) {
      for (int v : loop) used[static_cast<size_t>(v)] = true;
    }
  }
  for (MergedFace& face : faces) {
    for (std::vector<int>& loop : face.loops) {
      std::vector<int> out;
      for (size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        out.push_back(a);
        const Vec3 ab = minus(points[b], points[a]);
        const double length2 = dot(ab, ab);
        if (length2 <= 0) continue;
        std::vector<std::pair<double, int>> between;
        for (size_t p = 0; p < points.size(); ++p) {
          const int v = static_cast<int>(p);
          if (!used[p] || v == a || v == b) continue;
          const Vec3 ap = minus(points[p], points[a]);
          const double t = dot(ap, ab) / length2;
          if (t <= 0 || t >= 1) continue;
          const Vec3 off = minus(ap, scaled(ab, t));
          if (dot(off, off) <= tolerance::kMeshWeldMm * tolerance::kMeshWeldMm) between.push_back({t, v});
        }
        std::sort(between.begin(), between.end());
        for (const auto& [t, v] : between) out.push_back(v);
      }
      loop = out;
    }
  }
}

// A loop without spikes (a -> b -> a: a slit of no width, where rounding or an inserted vertex
// folds an edge back on itself) and without repeated consecutive vertices.
void removeSpikes(std::vector<int>& loop) {
  bool changed = true;
  while (changed && loop.size() >= 3) {
    changed = false;
    for (size_t i = 0; i < loop.size() && loop.size() >= 3; ++i) {
      const size_t n = loop.size();
      const int before = loop[(i + n - 1) % n], after = loop[(i + 1) % n];
      if (loop[i] == after) {
        loop.erase(loop.begin() + static_cast<long>(i));
        changed = true;
      } else if (before == after) {
        // Drop loop[i] and the repeated vertex after it.
        const size_t next = (i + 1) % n;
        loop.erase(loop.begin() + static_cast<long>(std::max(i, next)));
        loop.erase(loop.begin() + static_cast<long>(std::min(i, next)));
        changed = true;
      }
    }
  }
}

// Triangles of one merged face (loops of mesh vertices) wound counter-clockwise about its normal.
void triangulateMerged(const MergedFace& face, const std::vector<Vec3>& points, TriangleMesh* mesh, double flat) {
  std::vector<Loop> loops;
  std::vector<int> globalIndex;
  for (const std::vector<int>& loop : face.loops) {
    Loop positions;
    for (int v : loop) {
      positions.push_back(points[static_cast<size_t>(v)]);
      globalIndex.push_back(v);
    }
    loops.push_back(positions);
  }
  TriangleMesh local;
  addFaceTriangles(loops, face.normal, 0, &local, flat);
  for (const auto& t : local.triangles) {
    mesh->triangles.push_back({globalIndex[static_cast<size_t>(t[0])], globalIndex[static_cast<size_t>(t[1])],
                               globalIndex[static_cast<size_t>(t[2])]});
  }
}

// The plate's prism and its attached solids, each on its own.
std::vector<Plate> solidsOf(const Plate& plate) {
  std::vector<Plate> solids{plate};
  solids[0].attached.clear();
  solids.insert(solids.end(), plate.attached.begin(), plate.attached.end());
  return solids;
}

// The faces of the plate's solids as they are (they touch but never overlap).
std::vector<geometry::SolidFace> touchingFaces(const Plate& plate) {
  std::vector<geometry::SolidFace> faces;
  for (const Plate& solid : solidsOf(plate)) {
    for (geometry::SolidFace& face : geometry::solidFaces(solid)) faces.push_back(std::move(face));
  }
  return faces;
}

// The boundary of the union of the plate's solids, computed in 3D (unionBoundaryPolygons): each
// solid's triangles less their parts inside another solid or on a face touching it. For solids
// that meet on slanted planes or along an edge, where the faces of one plane alone do not tell.
std::vector<geometry::SolidFace> booleanFaces(const Plate& plate) {
  std::vector<TriangleMesh> meshes;
  for (const Plate& solid : solidsOf(plate)) meshes.push_back(prismMesh(solid, 0));
  std::vector<geometry::SolidFace> faces;
  for (BoundaryPolygon& polygon : unionBoundaryPolygons(meshes)) faces.push_back({{std::move(polygon.points)}, polygon.normal});
  return faces;
}

// `pinches`: keep a vertex where a merged face's contour touches itself (see addRegions).
TriangleMesh unionMesh(std::vector<geometry::SolidFace> solidFaces, double flat, bool pinches) {
  // Every vertex welded first, so that points the solids share are one point (and one grid point).
  VertexWelder welder;
  std::vector<geometry::SolidFace> faces;
  for (geometry::SolidFace& face : solidFaces) {
    for (Loop& loop : face.loops) {
      for (Vec3& p : loop) p = welder.points()[static_cast<size_t>(welder.add(p))];
    }
    if (loopArea(face.loops[0]) < tolerance::kEmptyAreaMm2) continue;  // a side of no height
    faces.push_back(std::move(face));
  }
  // Faces grouped by plane, in order of first appearance.
  std::vector<PlaneFaces> planes;
  for (const geometry::SolidFace& face : faces) {
    PlaneFaces* home = nullptr;
    for (PlaneFaces& plane : planes) {
      const double cosine = dot(plane.normal, face.normal);
      if (std::abs(cosine) < 1 - tolerance::kSquareCosine) continue;
      bool on = true;
      for (const Loop& loop : face.loops) {
        for (const Vec3& p : loop) on = on && std::abs(dot(minus(p, plane.origin), plane.normal)) <= tolerance::kMeshWeldMm;
      }
      if (!on) continue;
      home = &plane;
      (cosine > 0 ? plane.along : plane.against).push_back(&face);
      break;
    }
    if (home == nullptr) planes.push_back({face.normal, face.loops[0][0], {&face}, {}});
  }
  std::vector<MergedFace> merged;
  for (const PlaneFaces& plane : planes) {
    for (bool alongNormal : {true, false}) {
      // The solids' own vertices on this plane by their grid point in this orientation's frame.
      const PlaneFrame frame(plane.origin, alongNormal ? plane.normal : negated(plane.normal));
      std::map<std::pair<ClipperLib::cInt, ClipperLib::cInt>, int> known;
      for (const auto* list : {&plane.along, &plane.against}) {
        for (const geometry::SolidFace* face : *list) {
          for (const Loop& loop : face->loops) {
            for (const Vec3& p : loop) {
              const ClipperLib::IntPoint q = frame.toClipper(p);
              known.emplace(std::make_pair(q.X, q.Y), welder.add(p));
            }
          }
        }
      }
      addRegions(plane, alongNormal, welder, known, pinches, &merged);
    }
  }
  insertVerticesOnEdges(merged, welder.points());
  for (MergedFace& face : merged) {
    for (std::vector<int>& loop : face.loops) removeSpikes(loop);
    face.loops.erase(std::remove_if(face.loops.begin(), face.loops.end(),
                                    [](const std::vector<int>& loop) { return loop.size() < 3; }),
                     face.loops.end());
  }
  merged.erase(std::remove_if(merged.begin(), merged.end(), [](const MergedFace& face) { return face.loops.empty(); }),
               merged.end());
  TriangleMesh mesh;
  mesh.vertices = welder.points();
  for (const MergedFace& face : merged) triangulateMerged(face, mesh.vertices, &mesh, flat);
  // Only the vertices the triangles use, numbered in order of first use.
  std::vector<int> renumber(mesh.vertices.size(), -1);
  TriangleMesh used;
  for (auto& t : mesh.triangles) {
    for (int& v : t) {
      if (renumber[static_cast<size_t>(v)] < 0) {
        renumber[static_cast<size_t>(v)] = static_cast<int>(used.vertices.size());
        used.vertices.push_back(mesh.vertices[static_cast<size_t>(v)]);
      }
      v = renumber[static_cast<size_t>(v)];
    }
    used.triangles.push_back(t);
  }
  return used;
}

// The plate and its attached solids as closed shells of their own, in one mesh (they touch).
TriangleMesh shellsMesh(const Plate& plate, double flat) {
  Plate body = plate;
  body.attached.clear();
  TriangleMesh mesh = prismMesh(body, flat);
  for (const Plate& solid : plate.attached) {
    const TriangleMesh piece = prismMesh(solid, flat);
    const int first = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const auto& t : piece.triangles) mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  return mesh;
}

}  // namespace

TriangleMesh plateMesh(const Plate& plate) {
  // The sweeps' mesh, as it always was: the plate's prism and each attached solid a closed shell.
  return shellsMesh(plate, 0);
}

TriangleMesh plateSolidMesh(const Plate& plate) {
  // Candidates in order of preference, each checked as built (every edge in two opposite
  // triangles, and the volume of the solids, which touch but never overlap): the union with the
  // triangulation that makes no flat triangle, the union with the plain one (where collinear
  // holes leave it no ear: it may keep a flat triangle), each first from the solids' faces as
  // they are and then from the 3D union's boundary (unionBoundaryPolygons: solids meeting on
  // slanted planes, a mitre joint's wedges), and, where none passes (see docs/export.md), the
  // plate and its attached solids as the closed shells they are, touching, triangulated the same
  // two ways. A plate without attached solids is its prism.
  constexpr double flat = tolerance::kFlatCornerTwiceAreaMm2;
  const double expected = sixVolume(shellsMesh(plate, 0));
  const auto passes = [&](const TriangleMesh& mesh) {
    return everyEdgeInTwoOppositeTriangles(mesh) &&
           std::abs(sixVolume(mesh) - expected) <= tolerance::kUnionVolumeShare * std::abs(expected);
  };
  TriangleMesh mesh;
  bool found = false;
  if (!plate.attached.empty()) {
    // The faces per plane first (exact where the solids meet on common planes: the bytes of every
    // plate that passed before the 3D union came), then the 3D union's.
    for (int method = 0; method < 2 && !found; ++method) {
      const std::vector<geometry::SolidFace> faces = method == 0 ? touchingFaces(plate) : booleanFaces(plate);
      for (double corner : {flat, 0.0}) {
        mesh = unionMesh(faces, corner, method == 1);
        if (passes(mesh)) {
          found = true;
          break;
        }
      }
    }
  }
  if (!found) {
    mesh = shellsMesh(plate, flat);
    if (!passes(mesh)) mesh = shellsMesh(plate, 0);
  }
  // The plain triangulation may leave triangles of no area where holes line up: flipped away, and
  // kept only if the mesh still passes.
  TriangleMesh flipped = mesh;
  flipZeroAreaTriangles(flipped);
  if (flipped.triangles != mesh.triangles && passes(flipped)) mesh = std::move(flipped);
  splitPinchedVertices(mesh);
  return mesh;
}

std::optional<TriangleMesh> solidBooleanMesh(const std::vector<TriangleMesh>& solids,
                                             const std::vector<TriangleMesh>& removed) {
  std::vector<geometry::SolidFace> faces;
  double expected = 0;  // six times the volume the polygons bound
  for (BoundaryPolygon& polygon : booleanBoundaryPolygons(solids, removed)) {
    const Loop& points = polygon.points;
    for (size_t k = 1; k + 1 < points.size(); ++k) expected += dot(points[0], cross(points[k], points[k + 1]));
    faces.push_back({{std::move(polygon.points)}, polygon.normal});
  }
  for (double corner : {tolerance::kFlatCornerTwiceAreaMm2, 0.0}) {
    TriangleMesh mesh = unionMesh(faces, corner, true);
    splitEdgesInFourTriangles(mesh);
    if (!everyEdgeInTwoOppositeTriangles(mesh) ||
        std::abs(sixVolume(mesh) - expected) > tolerance::kUnionVolumeShare * std::abs(expected))
      continue;
    TriangleMesh flipped = mesh;
    flipZeroAreaTriangles(flipped);
    if (everyEdgeInTwoOppositeTriangles(flipped)) mesh = std::move(flipped);
    splitPinchedVertices(mesh);
    return mesh;
  }
  return std::nullopt;
}

}  // namespace desia
