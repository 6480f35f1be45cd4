// SPDX-License-Identifier: GPL-3.0-or-later
// Squaring a plan's ways out and its jointed plates' contact normals (plan_squaring.h).
#include "plate/plan_squaring.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

namespace desia {

namespace {

// An orthonormal basis of the span of `vectors`, to rounding: the vector that stands furthest out
// of the span so far is taken next (pivoting), until every one lies within tolerance::kSquareCosine
// of it. Pivoting takes the two furthest apart first: taken in the order given, two vectors a few
// degrees apart whose rounding differs by 5e-9 span a plane tilted by ten times as much, and faces
// squared to that plane block the plates sliding along them.
std::vector<Vec3> spanningBasis(std::vector<Vec3> vectors, const Vec3* first = nullptr) {
  std::vector<Vec3> basis;
  if (first) basis.push_back(normalized(*first));
  while (basis.size() < 3) {
    double largest = tolerance::kSquareCosine;
    int pick = -1;
    for (size_t k = 0; k < vectors.size(); ++k) {
      Vec3 e = vectors[k];
      for (const Vec3& b : basis) e = minus(e, scaled(b, dot(e, b)));
      vectors[k] = e;  // what is left of it out of the span so far
      if (norm(e) > largest) largest = norm(e), pick = static_cast<int>(k);
    }
    if (pick < 0) break;
    basis.push_back(normalized(vectors[static_cast<size_t>(pick)]));
  }
  return basis;
}

// `v` with its components along the basis taken out, or `v` itself when the basis spans all of
// space (nothing is square to three independent vectors).
Vec3 squaredTo(const Vec3& v, const std::vector<Vec3>& basis) {
  if (basis.size() >= 3) return v;
  Vec3 squared = v;
  for (const Vec3& b : basis) squared = minus(squared, scaled(b, dot(squared, b)));
  return squared;
}

}  // namespace

// Jointed plates are cut from a design given to a micrometre (plates-from-mesh writes 6 decimals):
// a face meant to slide along a plan direction can be off square to it by 1e-7 rad, past the
// blocking tests' tolerance::kDirection (README "Verdicts on computed normals"). A contact normal
// within tolerance::kSquareCosine of square to plan directions is made exactly square to them; one
// that blocks a way out by more is kept, and the swept check of every plate judges the shapes
// themselves.
Vec3 squaredToNearlySquare(const Vec3& v, const std::vector<Vec3>& others, const Vec3* first) {
  std::vector<Vec3> nearlySquare;
  for (const Vec3& other : others) {
    if (std::abs(dot(v, other)) < tolerance::kSquareCosine) nearlySquare.push_back(other);
  }
  return normalized(squaredTo(v, spanningBasis(nearlySquare, first)));
}

Vec3 squaredToPlan(Vec3 normal, const std::vector<Vec3>& directions) { return squaredToNearlySquare(normal, directions); }

namespace {

// A contact between the plates leaving k-th and later matters to the plan's steps only while the
// k-th leaves, along directions[k]: squared to that way out before any other (the basis starts
// with it), it is square to it to rounding. Squared to a basis of the other ways out alone, whose
// rounding tilts them by different 1e-9s, it could be left 3e-9 off square to it, past
// tolerance::kDirection: the LIZARD with step tenons from 30 degrees verified in memory and failed
// as written, plate 16 held by its mitre slide's face "1.8e-7 degrees against it".
Vec3 squaredToPlanFirstTo(const Vec3& normal, const std::vector<Vec3>& directions, size_t firstLeaving) {
  if (firstLeaving >= directions.size() || std::abs(dot(normal, directions[firstLeaving])) >= tolerance::kSquareCosine)
    return squaredToPlan(normal, directions);
  return squaredToNearlySquare(normal, directions, &directions[firstLeaving]);
}

}  // namespace

namespace {

// The other half of the same rounding: a way out is itself one of the design's vectors (a shared
// edge, a mitre's normal, a tenon's axis), off by as much: for a plate leaving across a mitre along a
// vector 6e-9 out of the plane of the face its tenon slides along, no normal can be squared to that
// and to the other ways out in that plane at once. So each way out within tolerance::kSquareCosine
// of square to faces of its plate against plates still in place (the contacts in `assembly`, part k
// leaving k-th) is first made exactly square to them; a way out that would turn by more stays as it
// is (a real block is kept, and the swept check judges the shapes).
// A way out several plates share (the planner makes them one vector) is squared once, to the faces
// of all of them, and stays one vector: squared plate by plate, plates leaving together would leave
// along vectors 4e-9 apart, and a face squared to one of them would block the other.
std::vector<Vec3> directionsSquaredToFaces(const Assembly& assembly, std::vector<Vec3> directions) {
  const std::vector<Vec3> planned = directions;
  std::vector<bool> done(directions.size(), false);
  for (size_t first = 0; first < directions.size(); ++first) {
    if (done[first]) continue;
    const Vec3 shared = planned[first];
    std::vector<size_t> sharing;  // the plates leaving along this very vector
    for (size_t k = first; k < planned.size(); ++k) {
      if (planned[k][0] == shared[0] && planned[k][1] == shared[1] && planned[k][2] == shared[2]) sharing.push_back(k);
    }
    std::vector<Vec3> nearlySquare;  // the faces' normals
    for (size_t k : sharing) {
      const int part = static_cast<int>(k);
      for (const Contact& contact : assembly.contacts) {
        const bool mine = (contact.a == part && contact.b > part) || (contact.b == part && contact.a > part);
        if (mine && std::abs(dot(contact.normal, shared)) < tolerance::kSquareCosine)
          nearlySquare.push_back(contact.normal);
      }
    }
    const Vec3 squared = squaredTo(shared, spanningBasis(nearlySquare));
    const bool nearby = norm(minus(squared, shared)) < tolerance::kSquareCosine;
    for (size_t k : sharing) {
      done[k] = true;
      if (nearby) directions[k] = normalized(squared);
    }
  }
  return directions;
}

}  // namespace

Assembly squaredPlanAssembly(Assembly assembly, std::vector<Vec3>* directions) {
  *directions = directionsSquaredToFaces(assembly, *directions);
  for (Contact& contact : assembly.contacts)
    contact.normal =
        squaredToPlanFirstTo(contact.normal, *directions, static_cast<size_t>(std::min(contact.a, contact.b)));
  return assembly;
}

// The contacts of jointed plates (part k = the k-th to leave) as an assembly for the tests, the
// plan's ways out and the contact normals squared to each other (squaredPlanAssembly).
Assembly jointedAssembly(const std::vector<PlateContact>& contacts, const std::vector<int>& position,
                         std::vector<Part> parts, std::vector<Vec3>* directions) {
  Assembly assembly;
  assembly.parts = std::move(parts);
  for (const PlateContact& contact : contacts)
    assembly.contacts.push_back({position[contact.a], position[contact.b], contact.normal, contact.area});
  return squaredPlanAssembly(std::move(assembly), directions);
}

}  // namespace desia
