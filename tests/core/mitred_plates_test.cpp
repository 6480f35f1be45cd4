// SPDX-License-Identifier: GPL-3.0-or-later
// Mitred plates from a closed low-poly mesh (plates-from-mesh): one plate per face whose outer face
// is the mesh face (its corners where the face's fitted plane meets its neighbours') and whose
// inner face lies the thickness inside it; the contacts computed from
// the plates' geometry are exactly the mesh's edges, each along the mitre (the dihedral angle's
// bisector); the result turns with the mesh; every refusal names what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "analysis/vec3.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

using Polygon = std::vector<int>;  // vertex indices, counter-clockwise seen from outside

struct Solid {
  std::vector<Vec3> points;
  std::vector<Polygon> faces;
};

// The faces of the convex hull of `points`: every plane through three of them with all others
// behind it, its points ordered by angle about their centre.
Solid convexSolid(const std::vector<Vec3>& points) {
  Solid solid{points, {}};
  Vec3 centre{0, 0, 0};
  for (const Vec3& p : points) centre = {centre[0] + p[0] / points.size(), centre[1] + p[1] / points.size(), centre[2] + p[2] / points.size()};
  std::set<std::vector<int>> seen;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        Vec3 normal = cross(minus(points[j], points[i]), minus(points[k], points[i]));
        if (norm(normal) < 1e-9) continue;
        normal = normalized(normal);
        if (dot(normal, minus(points[i], centre)) < 0) normal = negated(normal);
        const double offset = dot(normal, points[i]);
        std::vector<int> on;
        bool hull = true;
        for (int m = 0; m < n; ++m) {
          const double h = dot(normal, points[m]) - offset;
          if (h > 1e-7) hull = false;
          if (std::abs(h) <= 1e-7) on.push_back(m);
        }
        if (!hull || !seen.insert(on).second) continue;
        Vec3 mid{0, 0, 0};
        for (int m : on) mid = {mid[0] + points[m][0] / on.size(), mid[1] + points[m][1] / on.size(), mid[2] + points[m][2] / on.size()};
        const Vec3 u = normalized(minus(points[on[0]], mid)), v = cross(normal, u);
        std::sort(on.begin(), on.end(), [&](int a, int b) {
          return std::atan2(dot(minus(points[a], mid), v), dot(minus(points[a], mid), u)) <
                 std::atan2(dot(minus(points[b], mid), v), dot(minus(points[b], mid), u));
        });
        solid.faces.push_back(on);
      }
    }
  }
  return solid;
}

Solid cube(double size = 200) {
  std::vector<Vec3> points;
  for (double x : {-size / 2, size / 2}) {
    for (double y : {-size / 2, size / 2}) {
      for (double z : {-size / 2, size / 2}) points.push_back({x, y, z});
    }
  }
  return convexSolid(points);
}

constexpr double kPhi = 1.6180339887498949;

Solid icosahedron() {
  std::vector<Vec3> points;
  for (double a : {-1.0, 1.0}) {
    for (double b : {-1.0, 1.0}) {
      points.push_back({0, 100 * a, 100 * b * kPhi});
      points.push_back({100 * a, 100 * b * kPhi, 0});
      points.push_back({100 * b * kPhi, 0, 100 * a});
    }
  }
  return convexSolid(points);
}

Solid dodecahedron() {
  std::vector<Vec3> points;
  for (double x : {-1.0, 1.0}) {
    for (double y : {-1.0, 1.0}) {
      for (double z : {-1.0, 1.0}) points.push_back({100 * x, 100 * y, 100 * z});
    }
  }
  for (double a : {-1.0, 1.0}) {
    for (double b : {-1.0, 1.0}) {
      points.push_back({0, 100 * a / kPhi, 100 * b * kPhi});
      points.push_back({100 * a / kPhi, 100 * b * kPhi, 0});
      points.push_back({100 * b * kPhi, 0, 100 * a / kPhi});
    }
  }
  return convexSolid(points);
}

// Polygons fanned from their first vertex into triangles, as the OBJ reader does.
TriangleMesh triangulated(const Solid& solid) {
  TriangleMesh mesh;
  mesh.vertices = solid.points;
  for (const Polygon& face : solid.faces) {
    for (size_t k = 1; k + 1 < face.size(); ++k) mesh.triangles.push_back({face[0], face[k], face[k + 1]});
  }
  return mesh;
}

// An L-shaped prism (height 50 along z): the L has a reflex corner, so the prism has a concave edge.
Solid lPrism() {
  const std::vector<std::array<double, 2>> l{{100, 100}, {100, 200}, {0, 200}, {0, 0}, {200, 0}, {200, 100}};  // reflex corner first
  Solid solid;
  for (double z : {0.0, 50.0}) {
    for (const auto& p : l) solid.points.push_back({p[0], p[1], z});
  }
  solid.faces.push_back({0, 1, 2, 3, 4, 5});  // the top, counter-clockwise from above...
  for (int& v : solid.faces.back()) v += 6;
  solid.faces.push_back({0, 5, 4, 3, 2, 1});  // ...and the bottom, clockwise (its outside is below), fanned from the reflex corner
  for (int k = 0; k < 6; ++k) solid.faces.push_back({k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6});
  return solid;
}

Vec3 outwardNormal(const Solid& solid, const Polygon& face) {
  Loop loop;
  for (int v : face) loop.push_back(solid.points[v]);
  return normalized(loopNormal(loop));
}

// Faces (indices) that share an edge, each pair once: the mesh's face adjacency.
std::set<std::pair<int, int>> adjacentFaces(const Solid& solid) {
  std::set<std::pair<int, int>> pairs;
  for (size_t f = 0; f < solid.faces.size(); ++f) {
    for (size_t g = f + 1; g < solid.faces.size(); ++g) {
      int shared = 0;
      for (int v : solid.faces[f]) shared += std::count(solid.faces[g].begin(), solid.faces[g].end(), v) > 0;
      if (shared >= 2) pairs.insert({static_cast<int>(f), static_cast<int>(g)});
    }
  }
  return pairs;
}

// The solid's face each plate came from (its corners are that face's vertices, in that order).
std::vector<int> faceOfPlates(const Solid& solid, const MitredPlates& result) {
  std::vector<int> faceOf;
  for (const std::vector<int>& corners : result.cornerVertices) {
    int found = -1;
    for (size_t f = 0; f < solid.faces.size(); ++f) {
      const Polygon& face = solid.faces[f];
      if (face.size() != corners.size()) continue;
      const auto start = std::find(face.begin(), face.end(), corners[0]);
      if (start == face.end()) continue;
      Polygon rotated(start, face.end());
      rotated.insert(rotated.end(), face.begin(), start);
      if (rotated == corners) found = static_cast<int>(f);
    }
    faceOf.push_back(found);
  }
  return faceOf;
}

// Everything plates-from-mesh promises for a solid: one plate per face, the mesh face outside, the
// inner face at the thickness, and one contact per edge along the mitre.
void expectMitredPlates(const Solid& solid, double thickness, bool convex) {
  const TriangleMesh mesh = triangulated(solid);
  MitredPlateOptions options;
  options.thickness = thickness;
  const MitredPlates result = mitredPlatesFromMesh(mesh, options, "solid");
  ASSERT_EQ(result.plates.size(), solid.faces.size());
  const std::set<std::pair<int, int>> adjacent = adjacentFaces(solid);
  EXPECT_EQ(result.meshEdges, static_cast<int>(adjacent.size()));
  EXPECT_FALSE(result.reoriented);
  const std::vector<int> faceOf = faceOfPlates(solid, result);
  std::set<int> faces(faceOf.begin(), faceOf.end());
  EXPECT_EQ(faces.size(), solid.faces.size());
  EXPECT_EQ(faces.count(-1), 0u) << "a plate's outer face is no mesh face";
  for (size_t p = 0; p < result.plates.size(); ++p) {
    const Plate& plate = result.plates[p];
    EXPECT_EQ(plate.id, static_cast<int>(p) + 1);
    ASSERT_EQ(plate.bottom.size(), 1u);
    ASSERT_EQ(plate.top[0].size(), plate.bottom[0].size());
    const Vec3 normal = outwardNormal(solid, solid.faces[faceOf[p]]);
    for (size_t k = 0; k < plate.bottom[0].size(); ++k) {
      // The corner where the fitted planes meet, on a nanometre grid: the vertex, to rounding.
      EXPECT_LT(norm(minus(plate.bottom[0][k], solid.points[result.cornerVertices[p][k]])), 1e-8);
      EXPECT_NEAR(dot(normal, minus(plate.top[0][k], plate.bottom[0][0])), -thickness, 1e-9) << "plate " << plate.id << " corner " << k;
    }
    EXPECT_GT(dot(plateThicknessAxis(plate), negated(normal)), 1 - 1e-12) << "the plate lies inside the mesh";
  }
  const std::vector<PlateContact> contacts = computePlateContacts(result.plates, PlateOptions{});
  EXPECT_EQ(contacts.size(), adjacent.size());
  std::set<std::pair<int, int>> touching;
  for (const PlateContact& c : contacts) {
    const int fa = faceOf[c.a], fb = faceOf[c.b];
    touching.insert({std::min(fa, fb), std::max(fa, fb)});
    const Vec3 na = outwardNormal(solid, solid.faces[fa]), nb = outwardNormal(solid, solid.faces[fb]);
    const Vec3 bisectorNormal = normalized(minus(nb, na));  // out of a's side face at a convex edge
    if (convex) {
      EXPECT_NEAR(dot(c.normal, bisectorNormal), 1, 1e-9) << "plates " << c.a + 1 << " and " << c.b + 1;
    } else {
      EXPECT_NEAR(std::abs(dot(c.normal, bisectorNormal)), 1, 1e-9) << "plates " << c.a + 1 << " and " << c.b + 1;
    }
    EXPECT_GT(c.area, 0);
  }
  EXPECT_EQ(touching, adjacent);
  EXPECT_EQ(result.contacts.size(), contacts.size());
  // And the design reads as any plate design: valid, connected.
  EXPECT_NO_THROW(documentFromPlates(result.plates, PlateOptions{}, "solid"));
}

TEST(MitredPlates, CubeSixPlatesTwelveMitres) {
  const Solid solid = cube();
  ASSERT_EQ(solid.faces.size(), 6u);
  expectMitredPlates(solid, 12, true);
}

TEST(MitredPlates, DodecahedronTwelvePentagonsThirtyMitres) {
  const Solid solid = dodecahedron();
  ASSERT_EQ(solid.faces.size(), 12u);
  expectMitredPlates(solid, 6, true);
  // Three faces meet at every corner: every plate's inner corner is its neighbours' too.
  MitredPlateOptions options;
  options.thickness = 6;
  EXPECT_LT(mitredPlatesFromMesh(triangulated(solid), options, "dodecahedron").largestCornerMismatch, 1e-9);
}

TEST(MitredPlates, IcosahedronTwentyTrianglesThirtyMitres) {
  const Solid solid = icosahedron();
  ASSERT_EQ(solid.faces.size(), 20u);
  expectMitredPlates(solid, 6, true);
  // Five faces meet at every corner, symmetrically: the mitres still share one line there.
  MitredPlateOptions options;
  options.thickness = 6;
  EXPECT_LT(mitredPlatesFromMesh(triangulated(solid), options, "icosahedron").largestCornerMismatch, 1e-9);
}

TEST(MitredPlates, NonConvexFaceAndConcaveEdge) {
  const Solid solid = lPrism();
  expectMitredPlates(solid, 8, false);
  MitredPlateOptions options;
  options.thickness = 8;
  const MitredPlates result = mitredPlatesFromMesh(triangulated(solid), options, "l-prism");
  // The L plates keep their six corners; at the concave edge the inner face reaches past the outer.
  EXPECT_EQ(result.plates[0].bottom[0].size(), 6u);
  EXPECT_EQ(result.plates[1].bottom[0].size(), 6u);
}

TEST(MitredPlates, TurnsWithTheMesh) {
  const Solid solid = dodecahedron();
  TriangleMesh mesh = triangulated(solid);
  // About the axis (1, 2, 3) by 0.7 rad, then moved.
  const Vec3 axis = normalized({1, 2, 3});
  const double c = std::cos(0.7), s = std::sin(0.7);
  auto turn = [&](const Vec3& p) {
    const Vec3 r = scaled(p, c);
    const Vec3 k = scaled(cross(axis, p), s);
    const Vec3 a = scaled(axis, dot(axis, p) * (1 - c));
    return Vec3{r[0] + k[0] + a[0] + 1000, r[1] + k[1] + a[1] - 500, r[2] + k[2] + a[2] + 250};
  };
  TriangleMesh turned = mesh;
  for (Vec3& p : turned.vertices) p = turn(p);
  MitredPlateOptions options;
  options.thickness = 6;
  const MitredPlates original = mitredPlatesFromMesh(mesh, options, "dodecahedron");
  const MitredPlates moved = mitredPlatesFromMesh(turned, options, "turned");
  ASSERT_EQ(moved.plates.size(), original.plates.size());
  for (size_t p = 0; p < original.plates.size(); ++p) {
    ASSERT_EQ(moved.plates[p].bottom[0].size(), original.plates[p].bottom[0].size());
    for (size_t k = 0; k < original.plates[p].bottom[0].size(); ++k) {
      // (Both on their nanometre grid: apart by up to a grid cell's diagonal.)
      EXPECT_LT(norm(minus(moved.plates[p].bottom[0][k], turn(original.plates[p].bottom[0][k]))), 2e-9);
      EXPECT_LT(norm(minus(moved.plates[p].top[0][k], turn(original.plates[p].top[0][k]))), 2e-9);
    }
  }
  ASSERT_EQ(moved.contacts.size(), original.contacts.size());
  for (size_t k = 0; k < original.contacts.size(); ++k) {
    EXPECT_EQ(moved.contacts[k].a, original.contacts[k].a);
    EXPECT_EQ(moved.contacts[k].b, original.contacts[k].b);
    const Vec3 expected = minus(turn(original.contacts[k].normal), turn({0, 0, 0}));
    EXPECT_NEAR(dot(moved.contacts[k].normal, expected), 1, 1e-9);
  }
}

TEST(MitredPlates, InsideOutMeshIsTurnedOutward) {
  TriangleMesh mesh = triangulated(cube());
  MitredPlateOptions options;
  options.thickness = 10;
  const MitredPlates outward = mitredPlatesFromMesh(mesh, options, "cube");
  for (auto& tri : mesh.triangles) std::swap(tri[1], tri[2]);
  const MitredPlates turned = mitredPlatesFromMesh(mesh, options, "inside-out");
  EXPECT_TRUE(turned.reoriented);
  ASSERT_EQ(turned.plates.size(), outward.plates.size());
  for (size_t p = 0; p < outward.plates.size(); ++p) {
    EXPECT_EQ(turned.plates[p].bottom, outward.plates[p].bottom);
    EXPECT_EQ(turned.plates[p].top, outward.plates[p].top);
  }
}

TEST(MitredPlates, ExtraPointsOnAnEdgeAndRepeatedPositionsAreNoCorners) {
  // A cube whose top and front faces both pass through the middle of their shared edge (a
  // modelling tool's subdivision), written with every triangle's own copies of its vertices (STL-like).
  Solid solid = cube(100);
  const int middle = static_cast<int>(solid.points.size());
  int top = -1, front = -1;
  for (size_t f = 0; f < solid.faces.size(); ++f) {
    const Vec3 n = outwardNormal(solid, solid.faces[f]);
    if (n[2] > 0.5) top = static_cast<int>(f);
    if (n[1] < -0.5) front = static_cast<int>(f);
  }
  ASSERT_GE(top, 0);
  ASSERT_GE(front, 0);
  solid.points.push_back({0, -50, 50});
  for (int f : {top, front}) {
    Polygon& face = solid.faces[f];
    for (size_t k = 0; k < face.size(); ++k) {
      const Vec3& a = solid.points[face[k]];
      const Vec3& b = solid.points[face[(k + 1) % face.size()]];
      if (a[1] == -50 && b[1] == -50 && a[2] == 50 && b[2] == 50) {
        face.insert(face.begin() + static_cast<long>(k) + 1, middle);
        break;
      }
    }
    ASSERT_EQ(face.size(), 5u);
  }
  const TriangleMesh shared = triangulated(solid);
  TriangleMesh copies;
  for (const auto& tri : shared.triangles) {
    const int base = static_cast<int>(copies.vertices.size());
    for (int v : tri) copies.vertices.push_back(shared.vertices[v]);
    copies.triangles.push_back({base, base + 1, base + 2});
  }
  MitredPlateOptions options;
  options.thickness = 10;
  const MitredPlates result = mitredPlatesFromMesh(copies, options, "subdivided");
  ASSERT_EQ(result.plates.size(), 6u);
  for (const Plate& plate : result.plates) EXPECT_EQ(plate.bottom[0].size(), 4u);
  EXPECT_EQ(result.contacts.size(), 12u);
}

TEST(MitredPlates, MoreThanThreeFacesAtAnUnevenCornerStillMeetAtEveryEdge) {
  // A square pyramid with its apex off the middle: four faces meet there, unevenly.
  const Solid solid = convexSolid({{0, 0, 0}, {200, 0, 0}, {200, 200, 0}, {0, 200, 0}, {60, 90, 150}});
  ASSERT_EQ(solid.faces.size(), 5u);
  MitredPlateOptions options;
  options.thickness = 6;
  const MitredPlates result = mitredPlatesFromMesh(triangulated(solid), options, "pyramid");
  EXPECT_GT(result.largestCornerMismatch, 0.01);
  EXPECT_EQ(result.contacts.size(), 8u);
  expectMitredPlates(solid, 6, true);
}

// --- refusals ----------------------------------------------------------------------------------

void expectRefusal(const TriangleMesh& mesh, double thickness, const std::string& pattern) {
  MitredPlateOptions options;
  options.thickness = thickness;
  try {
    mitredPlatesFromMesh(mesh, options, "shape.obj");
    ADD_FAILURE() << "accepted; expected: " << pattern;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadInput);
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

TEST(MitredPlatesRefusals, ThicknessNotPositive) {
  const TriangleMesh mesh = triangulated(cube());
  expectRefusal(mesh, 0, "^shape\\.obj: the thickness must be a positive number of millimetres, found 0$");
  expectRefusal(mesh, -3, "found -3$");
  expectRefusal(mesh, std::nan(""), "found nan$");
}

// Issue 24: a thickness below the tolerance asked for a smaller one; a merge angle just over the
// limit was printed as the limit ("at most 30, found 30").
TEST(MitredPlatesRefusals, MessagesSayWhatIsTrue) {
  const TriangleMesh mesh = triangulated(cube());
  expectRefusal(mesh, 1e-9, "^shape\\.obj: the thickness \\(1e-09 mm\\) must be more than the tolerance \\(0\\.05 mm\\): give a larger thickness$");
  MitredPlateOptions options;
  options.thickness = 10;
  options.mergeAngleDegrees = 30.0001;
  try {
    mitredPlatesFromMesh(mesh, options, "shape.obj");
    ADD_FAILURE() << "a merge angle of 30.0001 was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "shape.obj: the merge angle must be more than 0 and at most 30 degrees, found 30.0001");
  }
}

TEST(MitredPlatesRefusals, ThicknessTooLargeForAFaceNamesItAndTheLargestThatFits) {
  // A 200 mm cube's faces keep an inner face up to just under 100 mm (less the tolerance).
  expectRefusal(triangulated(cube()), 120,
                "the thickness 120 mm is too large for face 1 \\(around \\(-100, 0, 0\\)\\): its inner face would lose the side "
                "along the edge from vertex 1 to vertex [0-9]+; this face allows at most about 99\\.97 mm: give a smaller thickness");
  MitredPlateOptions options;
  options.thickness = 99.9;
  EXPECT_EQ(mitredPlatesFromMesh(triangulated(cube()), options, "cube").plates.size(), 6u);
}

TEST(MitredPlatesRefusals, ThicknessTooLargeForTheShape) {
  // A tray: a 200 mm square box with a 120 mm pocket down to a floor 8 mm above the bottom; its rim
  // slopes 5 degrees inward (four faces, not one ring). Every face keeps an inner face at 10 mm,
  // but the floor's plate would reach 2 mm below the bottom.
  Solid solid;
  const double rimIn = 60 - 40 * std::tan(5 * 3.14159265358979 / 180);
  auto square = [&](double half, double z) {
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) solid.points.push_back({x * half, y * half, z});
  };
  square(100, 0);     // 0..3 bottom
  square(100, 60);    // 4..7 rim, outside
  square(60, rimIn);  // 8..11 rim, inside
  square(60, 8);      // 12..15 floor
  solid.faces.push_back({3, 2, 1, 0});
  solid.faces.push_back({12, 13, 14, 15});
  for (int k = 0; k < 4; ++k) {
    const int m = (k + 1) % 4;
    solid.faces.push_back({k, m, 4 + m, 4 + k});            // outside wall
    solid.faces.push_back({4 + k, 4 + m, 8 + m, 8 + k});    // rim
    solid.faces.push_back({8 + k, 8 + m, 12 + m, 12 + k});  // pocket wall
  }
  MitredPlateOptions options;
  options.thickness = 3;
  EXPECT_EQ(mitredPlatesFromMesh(triangulated(solid), options, "tray").plates.size(), 14u);
  // At 6 mm the floor's plate (z 2..8) and the bottom's (z 0..6) share 4 mm of wood under the
  // pocket: plates with mitred sides are checked for overlaps by their core prisms.
  expectRefusal(triangulated(solid), 6, "plate 1 and plate 2 overlap \\(their solids share 60 mm wide and more\\)");
  expectRefusal(triangulated(solid), 10,
                "the thickness 10 mm is too large for the shape: the inner corner of face 2 \\(around \\(0, 0, 8\\)\\) below vertex 13 "
                "\\(-60, -60, 8\\) lies outside the mesh at \\(-70, -70, -2\\)");
}

TEST(MitredPlatesRefusals, NotClosed) {
  TriangleMesh mesh = triangulated(cube());
  mesh.triangles.pop_back();
  expectRefusal(mesh, 10, "shape\\.obj: the mesh is not closed: edge between vertices [0-9]+ and [0-9]+ belongs to 1 triangle");
}

TEST(MitredPlatesRefusals, InconsistentOrientation) {
  TriangleMesh mesh = triangulated(cube());
  std::swap(mesh.triangles[3][1], mesh.triangles[3][2]);
  expectRefusal(mesh, 10, "the mesh is not consistently oriented: triangles [0-9]+ and [0-9]+ both run from vertex [0-9]+ \\(.*\\) to vertex");
}

// Two cubes of the same mesh, the second moved by `offset`.
TriangleMesh twoCubes(const Vec3& offset) {
  TriangleMesh mesh = triangulated(cube(100));
  const TriangleMesh second = mesh;
  const int base = static_cast<int>(mesh.vertices.size());
  for (Vec3 p : second.vertices) mesh.vertices.push_back({p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]});
  for (auto tri : second.triangles) mesh.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  return mesh;
}

TEST(MitredPlatesRefusals, NotManifold) {
  // Along an edge (the positions weld into one edge of four triangles), and at a vertex.
  expectRefusal(twoCubes({100, 100, 0}), 10, "the mesh is not manifold: the edge between vertex [0-9]+ \\(50, 50, -50\\) and vertex [0-9]+ \\(50, 50, 50\\) belongs to 4 triangles");
  expectRefusal(twoCubes({100, 100, 100}), 10, "the mesh is not manifold: the surface touches itself at vertex [0-9]+ \\(50, 50, 50\\)");
}

TEST(MitredPlatesRefusals, SeparatePieces) {
  expectRefusal(twoCubes({300, 0, 0}), 10, "the mesh has 2 separate closed pieces");
}

TEST(MitredPlatesRefusals, NonPlanarFace) {
  // One corner raised by 1 mm: the top's two triangles differ by less than the merge angle (one
  // face), but lie up to 0.25 mm off one plane.
  TriangleMesh mesh = triangulated(cube(200));
  for (Vec3& p : mesh.vertices) {
    if (p == Vec3{100, 100, 100}) p[2] = 101;
  }
  expectRefusal(mesh, 10, "face [0-9]+ \\(around .*\\) is not planar: its vertices lie up to 0\\.25 mm off one plane .* tolerance 0\\.05 mm");
}

TEST(MitredPlatesRefusals, FaceWithAHole) {
  // A square frame: its top and bottom are square rings.
  Solid solid;
  const double outer[4][2] = {{0, 0}, {90, 0}, {90, 90}, {0, 90}}, inner[4][2] = {{30, 30}, {60, 30}, {60, 60}, {30, 60}};
  for (double z : {0.0, 20.0}) {
    for (const auto& p : outer) solid.points.push_back({p[0], p[1], z});
    for (const auto& p : inner) solid.points.push_back({p[0], p[1], z});
  }
  auto o = [](int k, int level) { return (k % 4) + 8 * level; };
  auto i = [](int k, int level) { return 4 + (k % 4) + 8 * level; };
  for (int k = 0; k < 4; ++k) {
    solid.faces.push_back({o(k, 1), o(k + 1, 1), i(k + 1, 1), i(k, 1)});  // top ring
    solid.faces.push_back({o(k + 1, 0), o(k, 0), i(k, 0), i(k + 1, 0)});  // bottom ring
    solid.faces.push_back({o(k, 0), o(k + 1, 0), o(k + 1, 1), o(k, 1)});  // outside
    solid.faces.push_back({i(k + 1, 0), i(k, 0), i(k, 1), i(k + 1, 1)});  // the hole's walls
  }
  expectRefusal(triangulated(solid), 5, "face 1 \\(around \\(45, 45, 20\\)\\) has a hole");
}

TEST(MitredPlatesRefusals, FanOfANonConvexPolygonTurnsTrianglesOver) {
  // The L prism's top written as one OBJ polygon starting at a corner that does not see the whole
  // L: the reader's fan turns a triangle over.
  std::string obj;
  const Solid solid = lPrism();
  for (const Vec3& p : solid.points) obj += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  for (size_t f = 0; f < solid.faces.size(); ++f) {
    Polygon face = solid.faces[f];
    if (f == 0) std::rotate(face.begin(), face.begin() + 2, face.end());  // start at (0, 200)
    obj += "f";
    for (int v : face) obj += " " + std::to_string(v + 1);
    obj += "\n";
  }
  expectRefusal(parseObj(obj, "shape.obj"), 5, "the surface folds back onto itself between face [0-9]+ .* triangulate the faces");
}

// How far a loop's points lie from the plane through their centre square to its Newell normal (mm).
double largestOffPlane(const Loop& loop) {
  Vec3 normal{0, 0, 0}, centre{0, 0, 0};
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vec3& a = loop[k];
    const Vec3& b = loop[(k + 1) % loop.size()];
    normal = {normal[0] + (a[1] - b[1]) * (a[2] + b[2]), normal[1] + (a[2] - b[2]) * (a[0] + b[0]),
              normal[2] + (a[0] - b[0]) * (a[1] + b[1])};
    for (int i = 0; i < 3; ++i) centre[i] += a[i] / loop.size();
  }
  normal = normalized(normal);
  double largest = 0;
  for (const Vec3& p : loop) largest = std::max(largest, std::abs(dot(minus(p, centre), normal)));
  return largest;
}

TEST(MitredPlates, TheExampleSculpturesReadFromTheirFiles) {
  // The sculptures of examples/plate/ (make_sculptures.py) as a user's files.
  for (const auto& [name, plates] : std::vector<std::pair<std::string, size_t>>{{"dodecahedron", 12}, {"lizard", 38}}) {
    const std::string path = "examples/plate/" + name + ".obj";
    MitredPlateOptions options;
    options.thickness = 6;
    const MitredPlates result = mitredPlatesFromMesh(parseMesh(testing::readFileText(testing::projectPath(path)), path), options, path);
    EXPECT_EQ(result.plates.size(), plates) << name;
    EXPECT_EQ(result.contacts.size(), static_cast<size_t>(result.meshEdges)) << name;
    EXPECT_LT(result.largestCornerMismatch, 1e-4) << name;
    // The OBJ is written to a micrometre, so its faces are planar to 1e-7 mm only; the plates'
    // corners come from the fitted planes (on a nanometre grid), so every face of every plate, and
    // so every mitre, is planar to a few nanometres (1e-11 rad on these plates: normals that the
    // blocking tests' 1e-9 judge as the design means them), and stays within the file's rounding
    // of its mesh vertex.
    const TriangleMesh mesh = parseMesh(testing::readFileText(testing::projectPath(path)), path);
    for (const Plate& plate : result.plates) {
      EXPECT_LT(largestOffPlane(plate.bottom[0]), 5e-9) << name << " plate " << plate.id << " outer face";
      EXPECT_LT(largestOffPlane(plate.top[0]), 5e-9) << name << " plate " << plate.id << " inner face";
      for (size_t k = 0; k < plate.bottom[0].size(); ++k) {
        const size_t next = (k + 1) % plate.bottom[0].size();
        const Loop side{plate.bottom[0][k], plate.bottom[0][next], plate.top[0][next], plate.top[0][k]};
        EXPECT_LT(largestOffPlane(side), 5e-9) << name << " plate " << plate.id << " side " << k;
        double nearest = HUGE_VAL;
        for (const Vec3& vertex : mesh.vertices) nearest = std::min(nearest, norm(minus(vertex, plate.bottom[0][k])));
        EXPECT_LT(nearest, 1e-5) << name << " plate " << plate.id << " corner " << k;
      }
    }
  }
}

}  // namespace
}  // namespace desia
