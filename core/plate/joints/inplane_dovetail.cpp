// SPDX-License-Identifier: GPL-3.0-or-later
// An in-plane dovetail (a jigsaw key) between two plates lying in one plane, edge to edge: a
// trapezoid tab on the tab plate's side, widening away from its root, in a socket of the same
// shape (plus the clearance) cut through the socket plate. The shoulder and the tip (the contact's
// normal) stop the tab plate pushing in, the flanks (leaning back) stop it pulling out or sliding
// along the side; nothing stops either plate along the sheets' axis, both ways.
#include "plate/joints/inplane_dovetail.h"

#include <cmath>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/side_crossings.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// The plate's faces as distances along `axis` from `origin`: [low, high].
std::pair<double, double> facesAlong(const Plate& plate, const Vec3& origin, const Vec3& axis) {
  const double first = dot(minus(plate.bottom[0][0], origin), axis);
  const double second = dot(minus(plate.top[0][0], origin), axis);
  return {std::min(first, second), std::max(first, second)};
}

// Both plates' faces lie in the same two planes: one sheet, cut in two.
bool inOneSheet(const Plate& a, const Plate& b, const Vec3& axis) {
  const auto [aLow, aHigh] = facesAlong(a, a.bottom[0][0], axis);
  const auto [bLow, bHigh] = facesAlong(b, a.bottom[0][0], axis);
  return std::abs(aLow - bLow) < tolerance::kContactMm && std::abs(aHigh - bHigh) < tolerance::kContactMm;
}

class InplaneDovetailCut final : public JointCut {
 public:
  explicit InplaneDovetailCut(const InplaneDovetailSite& site) : site_(site) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions& options, PlateCuts& cuts) const override {
    // Reaching into the tab plate, so that the union joins them across rounding (as a tenon).
    cuts.added[site_.tabPlate].push_back(site_.tab(0, tolerance::kTenonRootOverlapMm));
    // Run back past the socket plate's side, so that the socket opens through it cleanly.
    cuts.removed[site_.socketPlate].push_back(site_.tab(options.clearance / 2, options.woodMargin));
  }

 private:
  InplaneDovetailSite site_;
};

}  // namespace

std::vector<Vec3> InplaneDovetailSite::exits() const { return {axis, negated(axis)}; }

Loop InplaneDovetailSite::tab(double grow, double back) const {
  auto at = [&](double s, double t) { return plus(origin, plus(scaled(along, s), scaled(intoSocket, t))); };
  // The flanks' lines moved out by `grow` square to themselves: at every depth t, `sideways` further
  // along the side; the tip moved out by `grow`, the root back by `back`.
  const double sideways = grow * std::sqrt(depth * depth + flare * flare) / depth;
  auto left = [&](double t) { return root0 - flare * t / depth - sideways; };
  auto right = [&](double t) { return root1 + flare * t / depth + sideways; };
  const double tip = depth + grow;
  return {at(left(-back), -back), at(right(-back), -back), at(right(tip), tip), at(left(tip), tip)};
}

namespace {

// The site with the tab on `tab` and the socket in `socket` (the plates of `contact`), or nothing.
std::optional<InplaneDovetailSite> siteWithTabOn(const std::vector<Plate>& plates, const PlateContact& contact,
                                                 int tab, int socket, const JointCutOptions& options,
                                                 const std::vector<int>& crossers) {
  const Plate& tabPlate = plates[static_cast<size_t>(tab)];
  const Plate& socketPlate = plates[static_cast<size_t>(socket)];
  const Vec3 axis = plateThicknessAxis(tabPlate);
  InplaneDovetailSite site;
  site.tabPlate = tab;
  site.socketPlate = socket;
  site.axis = axis;
  site.intoSocket = normalized(tab == contact.a ? contact.normal : negated(contact.normal));  // normal: a into b
  site.along = normalized(cross(axis, site.intoSocket));
  const Vec3& corner = contact.region[0];
  site.origin = minus(corner, scaled(axis, dot(minus(corner, tabPlate.bottom[0][0]), axis)));
  // The contact covers the sheet's whole thickness, or the tab would hang beside the socket.
  const auto [acrossLow, acrossHigh] = extentAlong(contact.region, site.origin, axis);
  if (acrossLow > tolerance::kContactMm || acrossHigh < plateThickness(tabPlate) - tolerance::kContactMm)
    return std::nullopt;
  const auto [sideFrom, sideTo] = extentAlong(contact.region, site.origin, site.along);
  const InplaneDovetailSizes& sizes = options.inplaneDovetail;
  // Beside the plates crossing both (the VDA corner's bars, issue 26: their slots are cut where they
  // pass through the side): in the longest stretch they leave free, as far either side of the side
  // as the tab on the whole side would reach, with the wood margin and both cuts' clearance between.
  const double reach = sizes.depth.of(sizes.width.of(sideTo - sideFrom)) + options.woodMargin + options.clearance;
  const auto [from, to] = clearStretchOfSide(plates, crossers, site.origin, site.along, site.intoSocket, sideFrom,
                                             sideTo, reach, options.woodMargin + options.clearance);
  const double width = sizes.width.of(to - from);
  if (width < options.shortestJoint) return std::nullopt;
  site.root0 = (from + to - width) / 2;
  site.root1 = (from + to + width) / 2;
  site.depth = sizes.depth.of(width);
  site.flare = sizes.slope * site.depth;
  if (site.depth < tolerance::kZeroLengthMm) return std::nullopt;  // no tab (tab() divides by it)
  // Wood beside the tab on the shared side, and the socket inside the socket plate with the wood
  // margin all round (from just inside its side: the socket opens there).
  const double margin = options.woodMargin + options.clearance / 2;
  if (site.root0 - site.flare - margin < from || site.root1 + site.flare + margin > to) return std::nullopt;
  const PlaneFrame frame(socketPlate.bottom[0][0], plateThicknessAxis(socketPlate));
  const Loop room = site.tab(margin, -tolerance::kFlushMm);
  if (areaAgainst({room}, faceRegion(socketPlate, ClipperLib::ctIntersection), frame, true) > tolerance::kEmptyAreaMm2)
    return std::nullopt;
  return site;
}

}  // namespace

std::optional<InplaneDovetailSite> inplaneDovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                         const JointCutOptions& options,
                                                         const std::vector<int>& crossers) {
  if (contact.crossing || contact.region.size() < 3 || facesOnContact(plates, contact) != 0) return std::nullopt;
  const Plate& a = plates[static_cast<size_t>(contact.a)];
  const Plate& b = plates[static_cast<size_t>(contact.b)];
  if (!isPrism(a) || !isPrism(b)) return std::nullopt;
  const Vec3 axis = plateThicknessAxis(a);
  // One plane: the axes parallel, the contact square to them (square sides), the faces level.
  if (std::abs(dot(axis, plateThicknessAxis(b))) < 1 - tolerance::kFacingCosine) return std::nullopt;
  if (std::abs(dot(axis, contact.normal)) > tolerance::kSquareCosine) return std::nullopt;
  if (!inOneSheet(a, b, axis)) return std::nullopt;
  // The tab on plate a, else (no room for its socket in b: a narrow plate, a hole) on plate b.
  std::optional<InplaneDovetailSite> site = siteWithTabOn(plates, contact, contact.a, contact.b, options, crossers);
  return site ? site : siteWithTabOn(plates, contact, contact.b, contact.a, options, crossers);
}

std::vector<Vec3> inplaneDovetailFaceNormals(const InplaneDovetailSite& site) {
  // A flank runs from the root out by `flare` over `depth`: its outward normal leans back.
  auto flank = [&](double side) {
    return normalized(minus(scaled(site.along, side * site.depth), scaled(site.intoSocket, site.flare)));
  };
  return {site.intoSocket, flank(1), flank(-1)};
}

CutFootprint inplaneDovetailFootprint(const InplaneDovetailSite& site, const JointCutOptions& options) {
  return {site.socketPlate, 3, site.tab(options.clearance / 2, 0)};
}

std::shared_ptr<const JointCut> jointCut(const InplaneDovetailSite& site) {
  return std::make_shared<InplaneDovetailCut>(site);
}

namespace {

class InplaneDovetailFamily final : public JointFamily {
 public:
  explicit InplaneDovetailFamily(const JointSetting& setting) : JointFamily(setting) {
    const InplaneDovetailSizes& sizes = options().inplaneDovetail;
    requireShare(sizes.width, "inplaneDovetail.width");
    requireShare(sizes.depth, "inplaneDovetail.depth", true);
    requireAtLeast(sizes.slope, kLeastFlankSlope, "inplaneDovetail.slope");
    for (const PlateContact& contact : graph().computedContacts)
      sites_.push_back(inplaneDovetailSiteOf(plates(), contact, options(), platesCrossingBoth(graph(), contact)));
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    const std::optional<InplaneDovetailSite>& site = sites_[static_cast<size_t>(contact)];
    return site && exitsLet(site->exits(), site->tabPlate, mover, d);
  }

  // The only ways the joint lets its plates part: out of the sheet, either way.
  void addWaysOut(int contact, int, std::vector<Vec3>& ways) const override {
    const std::optional<InplaneDovetailSite>& site = sites_[static_cast<size_t>(contact)];
    if (site) {
      for (const Vec3& exit : site->exits()) ways.push_back(exit);
    }
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const InplaneDovetailSite& site = siteOf(joint);
    std::vector<Vec3> normals = inplaneDovetailFaceNormals(site);
    if (site.tabPlate != joint.mover) {  // the mover has the socket
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const InplaneDovetailSite& site = siteOf(joint);
    footprints.push_back(inplaneDovetailFootprint(site, options()));
    // The tab stands on the tab plate's side from root0 to root1: the wood under its root.
    footprints.push_back(woodUnderAddedPiece(site.tabPlate, site.origin, site.along, site.intoSocket, site.root0, site.root1));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(siteOf(joint)));
  }

 private:
  const InplaneDovetailSite& siteOf(const PlateJoint& joint) const {
    return letJointSite(sites_[static_cast<size_t>(joint.contact)], "inplane-dovetail");
  }
  std::vector<std::optional<InplaneDovetailSite>> sites_;  // per contact
};

}  // namespace

std::unique_ptr<JointFamily> makeInplaneDovetailFamily(const JointSetting& setting) {
  return std::make_unique<InplaneDovetailFamily>(setting);
}

}  // namespace desia
