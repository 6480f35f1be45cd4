// SPDX-License-Identifier: GPL-3.0-or-later
// Shared checks for the plate joint tests, written apart from the core so that they judge it:
// volumes of meshes, a point test for a plate's inside, and the stepping check every joint
// family's sweep is compared with (issue 26: "tested as the others are").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/document.h"
#include "desia/plate.h"

namespace desia::testing {

// An example design of examples/plate/, read as the CLI reads it.
AssemblyDocument loadPlateExample(const std::string& name);

// An axis-aligned board from corner lo to corner hi; its thinnest extent is its thickness (as
// examples/plate/make_examples.py writes them).
Plate board(int id, const Vec3& lo, const Vec3& hi);

// The signed volume a closed, outward mesh encloses.
double meshVolume(const TriangleMesh& mesh);
// A plate's volume with its attached solids (its mesh holds them; they touch it, never overlap it).
double plateVolume(const Plate& plate);

// A plate's inside as a point test: between its face planes and inside the section there (each side
// is planar, so the section is its loops' vertices interpolated from the first face to the second),
// or inside one of its attached solids. Each loop is projected once, so stepping many points is fast.
class PlateInside {
 public:
  explicit PlateInside(const Plate& plate);
  bool contains(const Vec3& point) const;

 private:
  struct ProjectedLoop {
    std::vector<std::array<double, 2>> first, second;  // on the first face and on the second
  };
  Vec3 axis_, base_, u_, v_;
  double thickness_ = 0;
  std::vector<ProjectedLoop> loops_;
  std::vector<PlateInside> attached_;
};

// The jointed plates of a design's result in the order its plan takes them out (as
// verifyJointedPlates takes them).
std::vector<Plate> jointedInRemovalOrder(const PlateDesignResult& result);

// A design of `plates` (named `name`) and its result, written as the CLI writes them
// (plateDesignToJson) and read back.
AssemblyDocument writtenPlateResult(const std::vector<Plate>& plates, const PlateDesignResult& result,
                                    const std::string& name);

// `desia check` of a document (a result as written and read back), by the DBG test [0] and by the
// LP test [1].
std::array<CheckReport, 2> checkedByBothMethods(const AssemblyDocument& document);

// One axis of a sampling grid: points at from + offset, + step, ... below `to`.
struct SampleAxis {
  Vec3 direction;
  double from = 0, to = 0, step = 1;
};

// The grid's points (origin + a sum over the three axes) inside `plate`. Each axis starts a few
// hundredths of a millimetre past `from` (different on each axis), so that no sample lies on a
// face drawn at a round number.
std::vector<Vec3> samplesInside(const Plate& plate, const Vec3& origin, const std::array<SampleAxis, 3>& axes);

// The independent check of a sweep: the samples moved along d by half a step, then a step further
// each time, below reach; does any land inside the obstacle?
bool steppedCollision(const std::vector<Vec3>& samples, const Plate& obstacle, const Vec3& d, double step, double reach);

}  // namespace desia::testing
