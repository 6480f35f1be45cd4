// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/face_tenon.h"

#include <cmath>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// The block on the tenon plate: its footprint on the lap, into the mortise plate by the depth.
Plate faceTenonBlock(const FaceTenon& tenon) {
  Plate block;
  Loop onLap = tenon.footprint(0), inside;
  for (const Vec3& p : onLap) inside.push_back(plus(p, scaled(tenon.out, -tenon.depth)));
  block.bottom = {onLap};
  block.top = {inside};
  return block;
}

// The mortise plate's face the lap lies on: 0 its first, 1 its second.
int faceTenonMortiseFace(const std::vector<Plate>& plates, const FaceTenon& tenon) {
  return dot(tenon.out, plateThicknessAxis(plates[tenon.mortisePlate])) > 0 ? 1 : 0;
}

class FaceTenonCut final : public JointCut {
 public:
  explicit FaceTenonCut(const FaceTenon& tenon) : tenon_(tenon) {}
  // A blind mortise is a housing from the lap's face, as deep as the block (a dovetail's depth).
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    const int face = faceTenonMortiseFace(plates, tenon_);
    cuts.housings[tenon_.mortisePlate][face].push_back(tenon_.footprint(options.clearance / 2));
    cuts.housingDepth[tenon_.mortisePlate][face] = tenon_.depth;
    cuts.attached[tenon_.tenonPlate].push_back(faceTenonBlock(tenon_));
  }

 private:
  FaceTenon tenon_;
};

}  // namespace

Loop FaceTenon::footprint(double grow) const {
  auto at = [&](double s, double t) { return plus(origin, plus(scaled(u, s), scaled(v, t))); };
  return {at(s0 - grow, t0 - grow), at(s1 + grow, t0 - grow), at(s1 + grow, t1 + grow), at(s0 - grow, t1 + grow)};
}

std::optional<FaceTenon> faceTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const Vec3& d, const JointCutOptions& options) {
  const std::optional<int> partner = touchingPartnerOf(contact, tenonPlate);
  // A lap: the contact lies on a face of both plates.
  if (!partner || contact.region.size() < 3 || facesOnContact(plates, contact) != 2) return std::nullopt;
  FaceTenon tenon;
  tenon.tenonPlate = tenonPlate;
  tenon.mortisePlate = *partner;
  const Plate& mortise = plates[tenon.mortisePlate];
  if (!isPrism(plates[tenonPlate]) || !isPrism(mortise)) return std::nullopt;
  tenon.out = contact.a == tenonPlate ? negated(contact.normal) : contact.normal;
  if (dot(normalized(d), tenon.out) < 1 - tolerance::kDirection) return std::nullopt;  // straight off the lap only
  tenon.u = normalized(contact.edgeDirection);
  if (std::abs(dot(tenon.u, tenon.out)) > tolerance::kSquareCosine) return std::nullopt;
  tenon.v = normalized(cross(tenon.out, tenon.u));
  tenon.origin = contact.region[0];
  const auto [s0, s1] = extentAlong(contact.region, tenon.origin, tenon.u);
  const auto [t0, t1] = extentAlong(contact.region, tenon.origin, tenon.v);
  // The middle each way (by default the middle third): wood all round the mortise, and room for
  // other joints.
  const FaceTenonSizes& sizes = options.faceTenon;
  tenon.s0 = s0 + sizes.margin.of(s1 - s0);
  tenon.s1 = s1 - sizes.margin.of(s1 - s0);
  tenon.t0 = t0 + sizes.margin.of(t1 - t0);
  tenon.t1 = t1 - sizes.margin.of(t1 - t0);
  if (tenon.s1 - tenon.s0 < options.shortestJoint || tenon.t1 - tenon.t0 < options.shortestJoint) return std::nullopt;
  // By default as deep as a dovetail's housing: both faces may hold one.
  tenon.depth = sizes.depth.of(plateThickness(mortise));
  // The block inside the lap (a lap that is not a rectangle may not hold the middle).
  const PlaneFrame frame(tenon.origin, tenon.out);
  if (areaAgainst({tenon.footprint(0)}, {contact.region}, frame, true) > tolerance::kEmptyAreaMm2) return std::nullopt;
  return tenon;
}

std::vector<Vec3> faceTenonFaceNormals(const FaceTenon& tenon) {
  return {negated(tenon.out), tenon.u, negated(tenon.u), tenon.v, negated(tenon.v)};
}

CutFootprint faceTenonFootprint(const std::vector<Plate>& plates, const FaceTenon& tenon) {
  return {tenon.mortisePlate, faceTenonMortiseFace(plates, tenon) == 0 ? 1 : 2, tenon.footprint(0)};
}

std::shared_ptr<const JointCut> jointCut(const FaceTenon& tenon) { return std::make_shared<FaceTenonCut>(tenon); }

namespace {

class FaceTenonFamily final : public JointFamily {
 public:
  explicit FaceTenonFamily(const JointSetting& setting) : JointFamily(setting) {
    const FaceTenonSizes& sizes = options().faceTenon;
    requireShare(sizes.depth, "faceTenon.depth");
    if (!(sizes.margin.of(1) >= 0 && sizes.margin.of(1) < 0.5 && sizes.margin.denominator > 0))
      throwBadInput("", "the joint size faceTenon.margin must be a share of the lap from 0 to below a half");
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    return faceTenonOf(plates(), this->contact(contact), mover, d, options()).has_value();
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    return faceTenonFaceNormals(tenonOf(joint));
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    footprints.push_back(faceTenonFootprint(plates(), tenonOf(joint)));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(tenonOf(joint)));
  }

 private:
  FaceTenon tenonOf(const PlateJoint& joint) const {
    return letJointSite(faceTenonOf(plates(), contact(joint.contact), joint.mover, joint.direction, options()),
                        "face-tenon");
  }
};

}  // namespace

std::unique_ptr<JointFamily> makeFaceTenonFamily(const JointSetting& setting) {
  return std::make_unique<FaceTenonFamily>(setting);
}

}  // namespace desia
