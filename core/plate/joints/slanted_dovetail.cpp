// SPDX-License-Identifier: GPL-3.0-or-later
// A slanted sliding dovetail (see slanted_dovetail.h). Seen along the side, the tongue is a
// trapezoid from F's face (n = 0) to its far face (n = depth): its neck at the face centred on
// the side, its walls running with S's mid-plane (`lean` across per mm in) and flaring out by the
// dovetail's slope on each side, so it is wider at the far face than at the neck whatever the
// slant and no way but along the side takes it out. The slot is that trapezoid swept along the
// side from the stop on past F's edge, cut through F; the tongue is the trapezoid along the
// contact from the stop, attached to S.
#include "plate/joints/slanted_dovetail.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "desia/tolerances.h"
#include "plate/joints/dovetail.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/tenon.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// A point of the joint: `s` along the side, `c` across it on F's face, `n` into F.
Vec3 jointPoint(const SlantedDovetailSite& site, double s, double c, double n) {
  const SlantedSide& side = site.side;
  return plus(side.origin[0], plus(scaled(side.along, s), plus(scaled(site.width, c), scaled(side.intoMortise, n))));
}

// The site in the frame the square sliding dovetail measures its housing in (its across is
// `width`: c), to ask where the slot may open. That frame starts at S's vertex `edge` on its first
// face, which is the side's origin[0] (placeOnSide in slanted_tenon.cpp), so both measure s and c
// from the same point.
TenonSite housingFrame(const SlantedDovetailSite& site) {
  TenonSite edge;
  edge.tenonPlate = site.side.tenonPlate;
  edge.mortisePlate = site.side.mortisePlate;
  edge.edge = site.side.edge;
  edge.intoMortise = site.side.intoMortise;
  edge.along = site.side.along;
  edge.from = site.side.from;
  edge.to = site.side.to;
  edge.across = site.width;
  return edge;
}

// The tongue's walls (low, high in c) at depth n into F.
std::array<double, 2> wallsAt(const SlantedDovetailSite& site, double n) {
  const double f = n / site.depth;
  return {site.walls[0][0] + f * (site.walls[1][0] - site.walls[0][0]),
          site.walls[0][1] + f * (site.walls[1][1] - site.walls[0][1])};
}

// The section at s (the tongue's, walls moved out by `grow`) at depth n: its two corners.
std::array<Vec3, 2> cornersAt(const SlantedDovetailSite& site, double s, double n, double grow) {
  const std::array<double, 2> walls = wallsAt(site, n);
  return {jointPoint(site, s, walls[0] - grow, n), jointPoint(site, s, walls[1] + grow, n)};
}

// The slot's extent along the side: from the stop (moved back by `grow`) on past the open end's
// edge of F, as far as a square housing runs out.
std::pair<double, double> slotSpan(const std::vector<Plate>& plates, const SlantedDovetailCut& cut,
                                   const JointCutOptions& options, double grow) {
  const SlantedDovetailSite& site = cut.site;
  const auto run = housingRun(site.side.from, site.side.to, site.stop, site.reach, cut.openEnd);
  const double runOut = housingRunOut(plates[static_cast<size_t>(site.side.mortisePlate)], options);
  return cut.openEnd == 1 ? std::make_pair(run.first - grow, run.second + runOut)
                          : std::make_pair(run.first - runOut, run.second + grow);
}

class SlantedDovetailJointCut final : public JointCut {
 public:
  explicit SlantedDovetailJointCut(const SlantedDovetailCut& cut) : cut_(cut) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    cuts.attached[cut_.site.side.tenonPlate].push_back(slantedDovetailTongue(cut_));
    cuts.slanted[cut_.site.side.mortisePlate].push_back(
        slantedDovetailSlot(plates, cut_, options, options.clearance / 2));
  }

 private:
  SlantedDovetailCut cut_;
};

}  // namespace

std::vector<Vec3> SlantedDovetailSite::exits() const {
  std::vector<Vec3> ways;
  if (opens[0]) ways.push_back(negated(side.along));
  if (opens[1]) ways.push_back(side.along);
  return ways;
}

std::optional<SlantedDovetailSite> slantedDovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                         const JointCutOptions& options) {
  const std::optional<SlantedSide> side = slantedSideOf(plates, contact, options.slantedDovetail.leastDegrees, options);
  if (!side) return std::nullopt;
  SlantedDovetailSite site;
  site.side = *side;
  const Vec3 offset = minus(side->origin[1], side->origin[0]);
  site.sideWidth = norm(offset);
  if (site.sideWidth < tolerance::kZeroLengthMm) return std::nullopt;
  site.width = scaled(offset, 1 / site.sideWidth);
  site.lean = dot(side->out, site.width) / dot(side->out, side->intoMortise);
  const Plate& housingPlate = plates[static_cast<size_t>(side->mortisePlate)];
  site.depth = plateThickness(housingPlate);
  const double neck = options.dovetail.width.of(plateThickness(plates[static_cast<size_t>(side->tenonPlate)]));
  if (neck < options.dovetail.narrowestNeck) return std::nullopt;  // too thin a neck to mill
  const double centre = site.sideWidth / 2, farCentre = centre + site.lean * site.depth;
  const double flare = options.dovetail.slope * site.depth;
  site.walls = {{{centre - neck / 2, centre + neck / 2}, {farCentre - neck / 2 - flare, farCentre + neck / 2 + flare}}};
  const TenonSite edge = housingFrame(site);
  site.stop = housingStop(plates, edge, options.dovetail);
  if (side->to - side->from < site.stop + options.shortestJoint) return std::nullopt;
  // Seen along F's axis the slot covers both faces' sections: the strip from the lower wall to
  // the higher, which must lie where F has material on both its faces.
  const std::array<double, 2> strip{std::min(site.walls[0][0], site.walls[1][0]),
                                    std::max(site.walls[0][1], site.walls[1][1])};
  const HousingPlateFace face{faceRegion(housingPlate, ClipperLib::ctIntersection),
                              faceRegion(housingPlate, ClipperLib::ctUnion)};
  if (face.everywhere.empty() || face.anywhere.empty()) return std::nullopt;
  const HousingOpenings openings = housingOpenings(plates, edge, strip, site.stop, face, options, false);
  site.opens = openings.opens;
  site.reach = openings.reach;
  if (!site.opens[0] && !site.opens[1]) return std::nullopt;
  return site;
}

Plate slantedDovetailTongue(const SlantedDovetailCut& cut) {
  const SlantedDovetailSite& site = cut.site;
  const double s0 = cut.openEnd == 1 ? site.side.from + site.stop : site.side.from;
  const double s1 = cut.openEnd == 1 ? site.side.to : site.side.to - site.stop;
  auto section = [&](double s) {
    const std::array<Vec3, 2> face = cornersAt(site, s, 0, 0), far = cornersAt(site, s, site.depth, 0);
    return Loop{face[0], face[1], far[1], far[0]};
  };
  return solidOf(section(s0), section(s1));
}

std::array<Loop, 2> slantedDovetailSlot(const std::vector<Plate>& plates, const SlantedDovetailCut& cut,
                                        const JointCutOptions& options, double grow) {
  const SlantedDovetailSite& site = cut.site;
  const std::pair<double, double> span = slotSpan(plates, cut, options, grow);
  const double s0 = span.first, s1 = span.second;  // not a structured binding: C++17 lambdas cannot capture one
  auto outline = [&](double n) {
    const std::array<Vec3, 2> start = cornersAt(site, s0, n, grow), end = cornersAt(site, s1, n, grow);
    return Loop{start[0], end[0], end[1], start[1]};
  };
  const Plate& housingPlate = plates[static_cast<size_t>(site.side.mortisePlate)];
  if (entersFromFirstFace(housingPlate, site.side.intoMortise)) return {outline(0), outline(site.depth)};
  return {outline(site.depth), outline(0)};
}

std::vector<Vec3> slantedDovetailFaceNormals(const SlantedDovetailCut& cut) {
  const SlantedDovetailSite& site = cut.site;
  const Vec3& in = site.side.intoMortise;
  const double d = site.depth;
  const double lowRun = site.walls[1][0] - site.walls[0][0], highRun = site.walls[1][1] - site.walls[0][1];
  const Vec3 exit = cut.openEnd == 1 ? site.side.along : negated(site.side.along);
  return {in, normalized(plus(scaled(site.width, -d), scaled(in, lowRun))),
          normalized(minus(scaled(site.width, d), scaled(in, highRun))), negated(exit)};
}

CutFootprint slantedDovetailFootprint(const std::vector<Plate>& plates, const SlantedDovetailCut& cut,
                                      const JointCutOptions& options) {
  const SlantedDovetailSite& site = cut.site;
  const Plate& housingPlate = plates[static_cast<size_t>(site.side.mortisePlate)];
  const Vec3 axis = plateThicknessAxis(housingPlate);
  const auto [s0, s1] = slotSpan(plates, cut, options, 0);
  const double low = std::min(site.walls[0][0], site.walls[1][0]), high = std::max(site.walls[0][1], site.walls[1][1]);
  auto onFirst = [&](double s, double c) {
    const Vec3 p = jointPoint(site, s, c, 0);
    return minus(p, scaled(axis, dot(minus(p, housingPlate.bottom[0][0]), axis)));
  };
  return {site.side.mortisePlate, 3, {onFirst(s0, low), onFirst(s1, low), onFirst(s1, high), onFirst(s0, high)}};
}

std::shared_ptr<const JointCut> jointCut(const SlantedDovetailCut& cut) {
  return std::make_shared<SlantedDovetailJointCut>(cut);
}

namespace {

class SlantedDovetailFamily final : public JointFamily {
 public:
  explicit SlantedDovetailFamily(const JointSetting& setting) : JointFamily(setting) {
    requireAtLeast(options().slantedDovetail.leastDegrees, 1, "slantedDovetail.leastDegrees");
    for (const PlateContact& contact : graph().computedContacts)
      sites_.push_back(slantedDovetailSiteOf(plates(), contact, options()));
  }

  // Along the side towards an open end (exactly: see exitsLet).
  bool lets(int contact, int mover, const Vec3& d) const override {
    const std::optional<SlantedDovetailSite>& site = sites_[static_cast<size_t>(contact)];
    return site && exitsLet(site->exits(), site->side.tenonPlate, mover, d);
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const SlantedDovetailCut cut = cutOf(joint);
    std::vector<Vec3> normals = slantedDovetailFaceNormals(cut);
    if (cut.site.side.tenonPlate != joint.mover) {  // the mover has the slot
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const SlantedDovetailCut cut = cutOf(joint);
    footprints.push_back(slantedDovetailFootprint(plates(), cut, options()));
    // The tongue runs along the side from the stop to the open end: the wood under it.
    const SlantedSide& side = cut.site.side;
    const auto [start, end] = housingRun(side.from, side.to, cut.site.stop, {0, 0}, cut.openEnd);
    footprints.push_back(woodUnderAddedPiece(side.tenonPlate, side.origin[0], side.along, side.out, start, end));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(cutOf(joint)));
  }

 private:
  // The dovetail of a planned joint: its slot opens where the tongue plate leaves.
  SlantedDovetailCut cutOf(const PlateJoint& joint) const {
    SlantedDovetailCut cut;
    cut.site = *sites_[static_cast<size_t>(joint.contact)];
    const Vec3 exit = cut.site.side.tenonPlate == joint.mover ? joint.direction : negated(joint.direction);
    cut.openEnd = dot(exit, cut.site.side.along) > 0 ? 1 : 0;
    return cut;
  }
  std::vector<std::optional<SlantedDovetailSite>> sites_;  // per contact
};

}  // namespace

std::unique_ptr<JointFamily> makeSlantedDovetailFamily(const JointSetting& setting) {
  return std::make_unique<SlantedDovetailFamily>(setting);
}

}  // namespace desia
