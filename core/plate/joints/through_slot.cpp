// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/through_slot.h"

#include <algorithm>
#include <cmath>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/halved.h"
#include "plate/plane_frame.h"
#include "plate/plate_graph.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

class ThroughSlotCut final : public JointCut {
 public:
  ThroughSlotCut(int plate, Loop region) : plate_(plate), region_(std::move(region)) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions&, PlateCuts& cuts) const override {
    cuts.removed[plate_].push_back(region_);
  }

 private:
  int plate_;
  Loop region_;
};

// Some crossing of `plate` along the same line direction keeps it from leaving along d with
// halved joints.
bool halvedHoldsAlong(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts, int plate,
                      const Vec3& d) {
  for (const PlateContact& other : contacts) {
    if (!other.crossing || (other.a != plate && other.b != plate) || !parallel(other.edgeDirection, d)) continue;
    if (!halvedSlotsOpen(plates, other, plate, d)) return true;
  }
  return false;
}

// The slot at `clearance` grown by `margin` on its long sides and closed end: where wood must be
// left round it. At an open end the plate's outline crosses the slot, often at an angle (the VDA
// corner's bars cross the hexagons' sides at 60 degrees: the outline meets the slot's far wall
// 10.4 mm past its near one across an 18 mm slot), so the wood there tapers to the outline: the
// region stops short of the crossing's end by the grown slot's width (outlines crossing it 45
// degrees or more off its line; a sharper one refuses the site, never lets a sliver through).
Loop slotSurround(const std::vector<Plate>& plates, const PlateContact& crossing, const ThroughSlotSite& site,
                  double clearance, double margin) {
  const Vec3& line = crossing.edgeDirection;
  const Vec3 axis = plateThicknessAxis(plates[static_cast<size_t>(site.seated)]);
  const double width = plateThickness(plates[static_cast<size_t>(site.seated)]);
  const double pullBack = width + clearance + 2 * margin;
  double start = site.opens[0] ? crossing.crossingFrom + pullBack : crossing.crossingFrom - clearance / 2 - margin;
  double end = site.opens[1] ? crossing.crossingTo - pullBack : crossing.crossingTo + clearance / 2 + margin;
  // A crossing shorter than that: the closed end's wood alone.
  if (site.opens[0]) start = std::min(start, crossing.crossingTo);
  if (site.opens[1]) end = std::max(end, crossing.crossingFrom);
  auto at = [&](double t, double w) { return plus(crossing.crossingPoint, plus(scaled(line, t), scaled(axis, w))); };
  return {at(start, -clearance / 2 - margin), at(end, -clearance / 2 - margin), at(end, width + clearance / 2 + margin),
          at(start, width + clearance / 2 + margin)};
}

// Does the slotted plate leave options.woodMargin of wood round the slot (at the clearance) on its
// long sides and closed ends? A slot reaching the plate's side, or a hole, would leave a sliver
// or cut the plate open where the joint needs it whole.
bool slotLeavesWood(const std::vector<Plate>& plates, const PlateContact& crossing, const ThroughSlotSite& site,
                    const JointCutOptions& options) {
  const Plate& slotted = plates[static_cast<size_t>(site.slotted)];
  const PlaneFrame frame(slotted.bottom[0][0], plateThicknessAxis(slotted));
  const Loop surround = slotSurround(plates, crossing, site, options.clearance, options.woodMargin);
  return areaAgainst({surround}, faceRegion(slotted, ClipperLib::ctIntersection), frame, true) <=
         tolerance::kEmptyAreaMm2;
}

}  // namespace

std::optional<ThroughSlotSite> throughSlotSiteOf(const std::vector<Plate>& plates,
                                                 const std::vector<PlateContact>& contacts, int crossingIndex,
                                                 int seated, const JointCutOptions& options) {
  const PlateContact& crossing = contacts[static_cast<size_t>(crossingIndex)];
  if (!crossing.crossing || needsSlantedNotchWalls(plates, crossing)) return std::nullopt;
  ThroughSlotSite site;
  site.seated = seated;
  site.slotted = crossing.a == seated ? crossing.b : crossing.a;
  site.opens = crossing.a == seated ? crossing.bOpens : crossing.aOpens;
  // The slot must not cut the slotted plate in two. (Each end of the crossing is where one of
  // the two plates ends, so the seated plate then ends at it somewhere.)
  if (site.opens[0] && site.opens[1]) return std::nullopt;
  // Only where halved joints hold the seated plate along the line both ways (a bar through two
  // plates meeting edge to edge, whose slots open towards each other): elsewhere a through slot
  // frees too much (reciprocal designs, docs/plates.md).
  const Vec3& line = crossing.edgeDirection;
  if (!halvedHoldsAlong(plates, contacts, seated, line) || !halvedHoldsAlong(plates, contacts, seated, negated(line)))
    return std::nullopt;
  if (!slotLeavesWood(plates, crossing, site, options)) return std::nullopt;
  site.out = plateThicknessAxis(plates[static_cast<size_t>(site.slotted)]);
  return site;
}

Loop throughSlotRegion(const std::vector<Plate>& plates, const PlateContact& crossing, const ThroughSlotSite& site,
                       const JointCutOptions& options, double clearance) {
  const Vec3& line = crossing.edgeDirection;
  const Vec3 axis = plateThicknessAxis(plates[site.seated]);
  const double width = plateThickness(plates[site.seated]);
  // Run out past the outline where the slotted plate ends at the crossing (as a halved slot).
  const double out = crossing.crossingTo - crossing.crossingFrom + options.woodMargin;
  const double start = crossing.crossingFrom - (site.opens[0] ? out : clearance / 2);
  const double end = crossing.crossingTo + (site.opens[1] ? out : clearance / 2);
  auto at = [&](double t, double w) { return plus(crossing.crossingPoint, plus(scaled(line, t), scaled(axis, w))); };
  return {at(start, -clearance / 2), at(end, -clearance / 2), at(end, width + clearance / 2),
          at(start, width + clearance / 2)};
}

std::vector<Vec3> throughSlotFaceNormals(const std::vector<Plate>& plates, const PlateContact& crossing,
                                         const ThroughSlotSite& site) {
  const Vec3 axis = plateThicknessAxis(plates[site.seated]);
  std::vector<Vec3> normals{axis, negated(axis)};
  if (!site.opens[0]) normals.push_back(negated(crossing.edgeDirection));
  if (!site.opens[1]) normals.push_back(crossing.edgeDirection);
  return normals;
}

namespace {

class ThroughSlotFamily final : public JointFamily {
 public:
  explicit ThroughSlotFamily(const JointSetting& setting) : JointFamily(setting) {
    const std::vector<PlateContact>& contacts = graph().contacts;
    sites_.resize(contacts.size());
    for (size_t c = 0; c < contacts.size(); ++c) {
      for (int seated : {contacts[c].a, contacts[c].b}) {
        std::optional<ThroughSlotSite> site =
            throughSlotSiteOf(plates(), contacts, static_cast<int>(c), seated, options());
        if (site) sites_[c].push_back(*site);
      }
    }
  }

  bool joinsCrossings() const override { return true; }

  // Made joints only: the paper's planned model has halved joints alone at crossings.
  bool lets(int crossing, int mover, const Vec3& d) const override {
    return makesJoints(realization()) && siteLetting(crossing, mover, d) != nullptr;
  }

  void addWaysOut(int contact, int, std::vector<Vec3>& ways) const override {
    if (!makesJoints(realization())) return;
    for (const ThroughSlotSite& site : sites_[static_cast<size_t>(contact)]) ways.push_back(site.out);
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const ThroughSlotSite& site = siteOf(joint);
    std::vector<Vec3> normals = throughSlotFaceNormals(plates(), contact(joint.contact), site);
    if (site.seated != joint.mover) {
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }
  bool keepsOtherContacts() const override { return false; }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const ThroughSlotSite& site = siteOf(joint);
    // Open at an end, it runs out of the slotted plate's outline as a halved slot does.
    footprints.push_back({site.slotted, 3, throughSlotRegion(plates(), contact(joint.contact), site, options(), 0),
                          site.opens[0] || site.opens[1] ? FootprintKind::SlotRunningOut : FootprintKind::Cut});
  }

  void addCuts(const PlateJoint& joint, double clearance, JointCutList& cuts) const override {
    const ThroughSlotSite& site = siteOf(joint);
    cuts.push_back(std::make_shared<ThroughSlotCut>(
        site.slotted, throughSlotRegion(plates(), contact(joint.contact), site, options(), clearance)));
  }

 private:
  const ThroughSlotSite* siteLetting(int crossing, int mover, const Vec3& d) const {
    for (const ThroughSlotSite& site : sites_[static_cast<size_t>(crossing)]) {
      if (exitsLet({site.out, negated(site.out)}, site.seated, mover, d)) return &site;
    }
    return nullptr;
  }
  const ThroughSlotSite& siteOf(const PlateJoint& joint) const {
    const ThroughSlotSite* site = siteLetting(joint.contact, joint.mover, joint.direction);
    if (site == nullptr) throw Error(ErrorCode::Internal, "a through-slot joint where no through slot lets its plate out");
    return *site;
  }
  std::vector<std::vector<ThroughSlotSite>> sites_;  // per contact: each plate seated, where it may be
};

}  // namespace

std::unique_ptr<JointFamily> makeThroughSlotFamily(const JointSetting& setting) {
  return std::make_unique<ThroughSlotFamily>(setting);
}

}  // namespace desia
