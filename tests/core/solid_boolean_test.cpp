// SPDX-License-Identifier: GPL-3.0-or-later
// The union of closed solids (unionBoundaryPolygons, issue 28 item 11) on cases with an answer
// found another way: two boxes turned by arbitrary angles (the union's volume by inclusion and
// exclusion, their intersection's by clipping each box's faces by the other's half-spaces), boxes
// touching face to face, and plates whose attached solids meet them on slanted planes (a slanted
// tenon, a pocket's floor): one closed solid of the solids' volume.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "analysis/vec3.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "test_support.h"

namespace desia {
namespace {

// A box as 8 corners (bit k of the index: + or - along axis k) and its 12 triangles, outward.
struct Box {
  Vec3 centre, half;
  std::array<Vec3, 3> axes;
  Vec3 corner(int c) const {
    Vec3 p = centre;
    for (int k = 0; k < 3; ++k) p = plus(p, scaled(axes[k], ((c >> k) & 1 ? 1 : -1) * half[k]));
    return p;
  }
  // Faces as corner quads, each counter-clockwise seen from outside.
  std::vector<std::vector<Vec3>> faces() const {
    static const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    std::vector<std::vector<Vec3>> out;
    for (const auto& q : quads) out.push_back({corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])});
    return out;
  }
  TriangleMesh mesh() const {
    TriangleMesh mesh;
    for (const auto& face : faces()) {
      const int first = static_cast<int>(mesh.vertices.size());
      mesh.vertices.insert(mesh.vertices.end(), face.begin(), face.end());
      mesh.triangles.push_back({first, first + 1, first + 2});
      mesh.triangles.push_back({first, first + 2, first + 3});
    }
    return mesh;
  }
  double volume() const { return 8 * half[0] * half[1] * half[2]; }
};

// A rotation from three angles (about z, then y, then x), as the rotated coordinate axes.
std::array<Vec3, 3> rotation(double a, double b, double c) {
  auto turn = [](const Vec3& v, int axis, double angle) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    Vec3 out = v;
    out[i] = std::cos(angle) * v[i] - std::sin(angle) * v[j];
    out[j] = std::sin(angle) * v[i] + std::cos(angle) * v[j];
    return out;
  };
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  for (Vec3& axis : axes) axis = turn(turn(turn(axis, 2, a), 1, b), 0, c);
  return axes;
}

// Six times the volume bounded by polygons (each counter-clockwise seen from outside).
double sixVolumeOf(const std::vector<std::vector<Vec3>>& polygons) {
  double six = 0;
  for (const auto& polygon : polygons) {
    for (size_t k = 1; k + 1 < polygon.size(); ++k) six += dot(polygon[0], cross(polygon[k], polygon[k + 1]));
  }
  return six;
}

// The part of a convex polygon inside a box (Sutherland-Hodgman against its six half-spaces).
std::vector<Vec3> clippedTo(std::vector<Vec3> polygon, const Box& box) {
  for (int k = 0; k < 3 && !polygon.empty(); ++k) {
    for (double sign : {-1.0, 1.0}) {
      const Vec3 n = scaled(box.axes[k], sign);
      const double limit = dot(n, box.centre) + box.half[k];
      std::vector<Vec3> out;
      for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % polygon.size()];
        const double da = dot(n, a) - limit, db = dot(n, b) - limit;
        if (da <= 0) out.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(plus(a, scaled(minus(b, a), da / (da - db))));
      }
      polygon = out;
    }
  }
  return polygon;
}

// |A n B|: its boundary is A's faces inside B and B's faces inside A.
double intersectionVolume(const Box& a, const Box& b) {
  std::vector<std::vector<Vec3>> boundary;
  for (const auto& face : a.faces()) boundary.push_back(clippedTo(face, b));
  for (const auto& face : b.faces()) boundary.push_back(clippedTo(face, a));
  return sixVolumeOf(boundary) / 6;
}

double unionVolume(const std::vector<TriangleMesh>& solids) {
  std::vector<std::vector<Vec3>> boundary;
  for (const BoundaryPolygon& polygon : unionBoundaryPolygons(solids)) boundary.push_back(polygon.points);
  return sixVolumeOf(boundary) / 6;
}

TEST(SolidBoolean, TwoBoxesTurnedByArbitraryAnglesHaveTheVolumeOfInclusionAndExclusion) {
  // Angles from a fixed linear congruential sequence: the same cases on every platform.
  uint32_t state = 12345;
  auto next = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  int overlapping = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Box a{{0, 0, 0}, {20, 15, 10}, rotation(6.3 * next(), 6.3 * next(), 6.3 * next())};
    const Box b{{25 * next() - 12.5, 25 * next() - 12.5, 25 * next() - 12.5},
                {5 + 20 * next(), 5 + 20 * next(), 5 + 20 * next()},
                rotation(6.3 * next(), 6.3 * next(), 6.3 * next())};
    const double shared = intersectionVolume(a, b);
    overlapping += shared > 1 ? 1 : 0;
    const double expected = a.volume() + b.volume() - shared;
    EXPECT_NEAR(unionVolume({a.mesh(), b.mesh()}), expected, 1e-9 * expected) << "trial " << trial;
  }
  EXPECT_GE(overlapping, 30);
}

TEST(SolidBoolean, ABoxLessATurnedBoxHasTheVolumeLeft) {
  uint32_t state = 777;
  auto next = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  for (int trial = 0; trial < 20; ++trial) {
    const Box a{{0, 0, 0}, {20, 15, 10}, rotation(6.3 * next(), 6.3 * next(), 6.3 * next())};
    const Box b{{20 * next() - 10, 20 * next() - 10, 20 * next() - 10}, {4 + 8 * next(), 4 + 8 * next(), 4 + 8 * next()},
                rotation(6.3 * next(), 6.3 * next(), 6.3 * next())};
    std::vector<std::vector<Vec3>> boundary;
    for (const BoundaryPolygon& polygon : booleanBoundaryPolygons({a.mesh()}, {b.mesh()})) boundary.push_back(polygon.points);
    const double expected = a.volume() - intersectionVolume(a, b);
    EXPECT_NEAR(sixVolumeOf(boundary) / 6, expected, 1e-9 * a.volume()) << "trial " << trial;
  }
  // A cut flush with a face (the cube's top): the top goes where the cut covers it.
  const Box cube{{0, 0, 0}, {10, 10, 10}, rotation(0.2, 0.5, 0.9)};
  const Box slot{plus(cube.centre, scaled(cube.axes[2], 8)), {4, 20, 2}, cube.axes};
  std::vector<std::vector<Vec3>> boundary;
  for (const BoundaryPolygon& polygon : booleanBoundaryPolygons({cube.mesh()}, {slot.mesh()})) boundary.push_back(polygon.points);
  EXPECT_NEAR(sixVolumeOf(boundary) / 6, 8000 - 8 * 20 * 4, 1e-9 * 8000);
}

TEST(SolidBoolean, BoxesTouchingFaceToFaceLoseTheFaceTheyShare) {
  const std::array<Vec3, 3> axes = rotation(0.3, 0.7, 1.1);
  const Box a{{0, 0, 0}, {10, 5, 5}, axes};
  // b's face -x on a's face +x, smaller than it: the touching part of both faces goes.
  const Box b{plus(scaled(axes[0], 14), scaled(axes[1], 1)), {4, 2, 3}, axes};
  const std::vector<BoundaryPolygon> boundary = unionBoundaryPolygons({a.mesh(), b.mesh()});
  int onShared = 0;
  for (const BoundaryPolygon& polygon : boundary) {
    // b's face -x and a's face +x (only the part of it beyond b's face is left of it).
    const double along = dot(polygon.normal, axes[0]);
    if (polygon.solid == 1 && along < -0.5) ++onShared;
    if (polygon.solid == 0 && along > 0.5) {
      for (const Vec3& p : polygon.points) {
        const double y = dot(minus(p, a.centre), axes[1]) - 1, z = dot(minus(p, a.centre), axes[2]);
        EXPECT_FALSE(std::abs(y) < 2 - 1e-6 && std::abs(z) < 3 - 1e-6) << "a point inside b's face";
      }
    }
  }
  EXPECT_EQ(onShared, 0);
  EXPECT_NEAR(unionVolume({a.mesh(), b.mesh()}), a.volume() + b.volume(), 1e-9 * a.volume());
}

Plate prism(const Loop& bottom, const Vec3& offset) {
  Plate plate;
  plate.bottom = {bottom};
  Loop top;
  for (const Vec3& p : bottom) top.push_back(plus(p, offset));
  plate.top = {top};
  return plate;
}

double plateVolume(const Plate& plate) {
  double volume = 0;
  Plate body = plate;
  body.attached.clear();
  volume += testing::enclosedVolume(plateMesh(body));
  for (const Plate& solid : plate.attached) volume += testing::enclosedVolume(plateMesh(solid));
  return volume;
}

void expectOneSolid(const TriangleMesh& mesh, double volume, const std::string& what) {
  EXPECT_EQ(testing::manifoldProblem(mesh), "") << what;
  EXPECT_NEAR(testing::enclosedVolume(mesh), volume, 1e-9 * volume) << what;
  int flat = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    flat += norm(cross(minus(mesh.vertices[static_cast<size_t>(t[1])], a), minus(mesh.vertices[static_cast<size_t>(t[2])], a))) <= 1e-9 ? 1 : 0;
  }
  EXPECT_EQ(flat, 0) << what;
}

TEST(SolidBoolean, ATenonOnASlantedSideOfAPlateIsOneSolidWithIt) {
  // A 100 x 50 x 10 board with a mitred end (its side from x = 100 at z = 0 to x = 90 at z = 10),
  // and a tenon standing on that slanted side, reaching past its top edge: they meet on the slant.
  Plate plate;
  plate.id = 1;
  plate.bottom = {{{0, 0, 0}, {100, 0, 0}, {100, 50, 0}, {0, 50, 0}}};
  plate.top = {{{0, 0, 10}, {90, 0, 10}, {90, 50, 10}, {0, 50, 10}}};
  const Vec3 slant = normalized(Vec3{10, 0, 1});  // the mitred side's outward normal
  const Vec3 along = normalized(Vec3{-1, 0, 10});  // up the slant
  const Vec3 base{100, 15, 0};
  auto onSide = [&](double up, double y) { return plus(plus(base, scaled(along, up)), Vec3{0, y, 0}); };
  const Plate tenon = prism({onSide(2, 0), onSide(2, 20), onSide(8, 20), onSide(8, 0)}, scaled(slant, 12));
  plate.attached = {tenon};
  const std::vector<BoundaryPolygon> boundary =
      unionBoundaryPolygons({plateMesh(Plate{1, "", plate.bottom, plate.top, {}}), plateMesh(tenon)});
  double six = 0;
  for (const BoundaryPolygon& polygon : boundary) {
    for (size_t k = 1; k + 1 < polygon.points.size(); ++k)
      six += dot(polygon.points[0], cross(polygon.points[k], polygon.points[k + 1]));
  }
  EXPECT_NEAR(six / 6, plateVolume(plate), 1e-9 * plateVolume(plate));
  expectOneSolid(plateSolidMesh(plate), plateVolume(plate), "slanted tenon");
}

TEST(SolidBoolean, APocketFloorInATiltedPlatesNotchIsOneSolidWithIt) {
  // A board tilted about x by 0.4 rad, a notch cut through its edge, and a floor milled in the
  // notch (an attached solid filling its lower third): plate less the notch plus the floor.
  const std::array<Vec3, 3> axes = rotation(0, 0, 0.4);
  auto at = [&](double x, double y, double z) {
    return plus(plus(scaled(axes[0], x), scaled(axes[1], y)), scaled(axes[2], z));
  };
  Plate plate;
  plate.id = 2;
  plate.bottom = {{at(0, 0, 0), at(40, 0, 0), at(40, 30, 0), at(25, 30, 0), at(25, 20, 0), at(15, 20, 0),
                   at(15, 30, 0), at(0, 30, 0)}};
  plate.top = plate.bottom;
  for (Vec3& p : plate.top[0]) p = plus(p, at(0, 0, 12));
  plate.attached = {prism({at(15, 20, 0), at(25, 20, 0), at(25, 30, 0), at(15, 30, 0)}, at(0, 0, 4))};
  expectOneSolid(plateSolidMesh(plate), plateVolume(plate), "pocket floor");
  EXPECT_NEAR(plateVolume(plate), (40 * 30 - 10 * 10) * 12 + 10 * 10 * 4, 1e-9);
}

}  // namespace
}  // namespace desia
