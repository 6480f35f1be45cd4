// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/through_slot.h"

#include <cmath>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/halved.h"
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

}  // namespace

namespace {

// Would a halved joint on `crossing` let `mover` leave the other plate along `d` (along the line)?
// As the halved family: the mover's slot opens behind it, the other's ahead.
bool halvedOpens(const PlateContact& crossing, int mover, const Vec3& d) {
  const bool ahead = dot(d, crossing.edgeDirection) > 0;
  const std::array<bool, 2>& moverOpens = crossing.a == mover ? crossing.aOpens : crossing.bOpens;
  const std::array<bool, 2>& otherOpens = crossing.a == mover ? crossing.bOpens : crossing.aOpens;
  return moverOpens[ahead ? 0 : 1] && otherOpens[ahead ? 1 : 0];
}

// Some crossing of `plate` along the same line direction keeps it from leaving along d with
// halved joints.
bool halvedHoldsAlong(const std::vector<PlateContact>& contacts, int plate, const Vec3& d) {
  for (const PlateContact& other : contacts) {
    if (!other.crossing || (other.a != plate && other.b != plate) || !parallel(other.edgeDirection, d)) continue;
    if (!halvedOpens(other, plate, d)) return true;
  }
  return false;
}

}  // namespace

std::optional<ThroughSlotSite> throughSlotSiteOf(const std::vector<Plate>& plates,
                                                 const std::vector<PlateContact>& contacts, int crossingIndex,
                                                 int seated) {
  const PlateContact& crossing = contacts[static_cast<size_t>(crossingIndex)];
  if (!crossing.crossing || needsSlantedNotchWalls(plates, crossing)) return std::nullopt;
  ThroughSlotSite site;
  site.seated = seated;
  site.slotted = crossing.a == seated ? crossing.b : crossing.a;
  site.opens = crossing.a == seated ? crossing.bOpens : crossing.aOpens;
  const std::array<bool, 2>& seatedOpens = crossing.a == seated ? crossing.aOpens : crossing.bOpens;
  // The slot must not cut the slotted plate in two, and the seated plate must end at the crossing
  // somewhere (else the crossing spans the slotted plate's width).
  if ((site.opens[0] && site.opens[1]) || !(seatedOpens[0] || seatedOpens[1])) return std::nullopt;
  // Only where halved joints hold the seated plate along the line both ways (a bar through two
  // plates meeting edge to edge, whose slots open towards each other): elsewhere a through slot
  // frees too much (reciprocal designs, docs/plates.md).
  const Vec3& line = crossing.edgeDirection;
  if (!halvedHoldsAlong(contacts, seated, line) || !halvedHoldsAlong(contacts, seated, negated(line)))
    return std::nullopt;
  site.out = plateThicknessAxis(plates[site.slotted]);
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
        std::optional<ThroughSlotSite> site = throughSlotSiteOf(plates(), contacts, static_cast<int>(c), seated);
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
    footprints.push_back({site.slotted, 3, throughSlotRegion(plates(), contact(joint.contact), site, options(), 0)});
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
    return *siteLetting(joint.contact, joint.mover, joint.direction);
  }
  std::vector<std::vector<ThroughSlotSite>> sites_;  // per contact: each plate seated, where it may be
};

}  // namespace

std::unique_ptr<JointFamily> makeThroughSlotFamily(const JointSetting& setting) {
  return std::make_unique<ThroughSlotFamily>(setting);
}

}  // namespace desia
