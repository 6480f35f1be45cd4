// SPDX-License-Identifier: GPL-3.0-or-later
// The joint model of a node of the plate planner's construction tree (paper Section 5.2: the
// contacts its joints will have, which the interlocking tests judge), and a complete plan made
// real: its joints cut into the plates and verified on them.
#pragma once

#include <memory>
#include <vector>

#include "desia/analysis.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "plate/joints/joint_families.h"
#include "plate/joints/plate_cuts.h"
#include "plate/plate_graph.h"

namespace desia {

// A node's joint model (jointModel) and its base directions, as the node test made them.
struct JointNodeModel {
  Assembly model;
  std::vector<BaseDirection> bases;
};

// One planned step: plate P_i leaves along d_i; its joints with the plates of R'_i.
struct PlanStep {
  int plate = -1;
  Vec3 direction{0, 0, 0};
  std::vector<PlateJoint> joints;
  int emptyJoints = 0;
  bool blocked = false;  // a crossing plate cannot part along the direction, or the joints' cuts collide
  std::vector<CutFootprint> cuts;  // where the joints cut into the plates (joints made only)
  // The model of the node this step ends in, from the node test that accepted it, until the LP
  // test on entering the node has used it (made once, not twice: 9 % of the icosahedron's search).
  std::shared_ptr<const JointNodeModel> nodeModel;
};

// The assembly of A_i: parts 0..i-1 are the steps' plates, part i (when any plate is left) is R_i.
Assembly jointModel(const PlateGraph& graph, const JointFamilies& families, const std::vector<PlanStep>& steps);

// Do the contact normals lie along at most three mutually square lines? (The LP test then adds
// nothing to the DBG test.)
bool hasSquareNormalsOnly(const Assembly& model);

// A complete plan made real: its joints cut into the plates (no clearance: the geometry the tests
// judge), in input order, and its verification on them (in removal order, as `desia check` reads
// the result: verifyJointedPlates).
struct JointedPlan {
  std::vector<Plate> plates;
  PlateRemovalVerification verification;
};

// The plates with the joints cut into them (and their milled solids attached).
std::vector<Plate> jointedPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                                 const std::vector<PlateJoint>& joints, double clearance,
                                 const JointCutOptions& options);

// The plates with the plan's joints cut, validated and snapped to their design as any plate read
// from a file is (so that the plates verified are the plates `desia check` reads back).
std::vector<Plate> cutPlates(const std::vector<Plate>& plates, const JointFamilies& families,
                             const std::vector<PlateJoint>& joints, const PlateOptions& geometry, double clearance,
                             const JointCutOptions& options);

// The plan (`order`: plate indices, the key first; `directions[k]`: the way out of order[k]) cut
// and verified.
JointedPlan cutPlan(const std::vector<Plate>& plates, const JointFamilies& families, const std::vector<PlateJoint>& joints,
                    const std::vector<int>& order, const std::vector<Vec3>& directions, const PlateOptions& geometry,
                    const JointCutOptions& options);

}  // namespace desia
