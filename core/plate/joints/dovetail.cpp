// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/dovetail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// A sliding dovetail's section (paper Fig. 2, right), across the edge plate's thickness `across`
// (c, from its first face) and into the face plate (n, from its face): the tongue is `wide` at
// the housing's floor, n = depth, and narrower by the lean on each side at the face, n = 0, so it
// cannot be pulled out; centred on the edge plate. The lean, the depth and the width are
// DovetailSizes (by default 1 in 6, a common dovetail slope; a third of the way through the face
// plate, so that housings from opposite faces leave a third between them; two thirds of the edge
// plate's thickness).
struct DovetailSection {
  double centre = 0, wide = 0, narrow = 0, depth = 0;
};

DovetailSection dovetailSection(const std::vector<Plate>& plates, const TenonSite& edge, const DovetailSizes& sizes) {
  DovetailSection section;
  const double thickness = plateThickness(plates[edge.tenonPlate]);
  section.centre = thickness / 2;
  section.depth = sizes.depth.of(plateThickness(plates[edge.mortisePlate]));
  section.wide = sizes.width.of(thickness);
  section.narrow = section.wide - 2 * sizes.slope * section.depth;
  return section;
}

// The housing's extent along the edge: from the stop to the open end.
std::pair<double, double> housingSpan(const std::vector<Plate>& plates, const DovetailCut& cut,
                                      const DovetailSizes& sizes) {
  const TenonSite& edge = cut.site.edge;
  return housingRun(edge.from, edge.to, housingStop(plates, edge, sizes), cut.site.reach, cut.openEnd);
}

// A point of the joint: `s` along the edge, `c` across the edge plate, `n` into the face plate.
Vec3 jointPoint(const std::vector<Plate>& plates, const TenonSite& edge, double s, double c, double n) {
  const Vec3 base = plates[edge.tenonPlate].bottom[0][edge.edge];
  return plus(base, plus(scaled(edge.along, s), plus(scaled(edge.across, c), scaled(edge.intoMortise, n))));
}

// A prism along the edge from s0 to s1 with the given section corners (c, n): a Plate whose two
// faces are its ends.
Plate prismAlongEdge(const std::vector<Plate>& plates, const TenonSite& edge, double s0, double s1,
                     const std::vector<std::array<double, 2>>& section) {
  Plate prism;
  Loop first, second;
  for (const auto& [c, n] : section) {
    first.push_back(jointPoint(plates, edge, s0, c, n));
    second.push_back(jointPoint(plates, edge, s1, c, n));
  }
  prism.bottom.push_back(first);
  prism.top.push_back(second);
  return prism;
}

// How far past the contact's start (end 0) or end (end 1) the two sides of a housing strip,
// [low, high] across the edge plate, run inside the face plate's outline before they leave it:
// the nearer and the farther; nothing where one never leaves.
std::optional<std::array<double, 2>> stripExits(const std::vector<Plate>& plates, const TenonSite& edge, const Loop& outline,
                                const PlaneFrame& frame, int end, double low, double high) {
  const double sign = end == 1 ? 1 : -1, at = end == 1 ? edge.to : edge.from;
  auto planar = [&](const Vec3& p) { return std::array<double, 2>{dot(frame.offset(p), frame.u), dot(frame.offset(p), frame.v)}; };
  const Vec3 way = scaled(edge.along, sign);
  const std::array<double, 2> dir{dot(way, frame.u), dot(way, frame.v)};
  std::array<double, 2> exits{};
  for (int side = 0; side < 2; ++side) {
    const std::array<double, 2> p = planar(jointPoint(plates, edge, at, side == 0 ? low : high, 0));
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < outline.size(); ++k) {
      const std::array<double, 2> q0 = planar(outline[k]), q1 = planar(outline[(k + 1) % outline.size()]);
      const double ex = q1[0] - q0[0], ey = q1[1] - q0[1];
      const double denominator = dir[0] * ey - dir[1] * ex;
      if (std::abs(denominator) < tolerance::kZeroDivisor) continue;  // the side runs along the strip
      const double wx = q0[0] - p[0], wy = q0[1] - p[1];
      const double t = (wx * ey - wy * ex) / denominator, u = (wx * dir[1] - wy * dir[0]) / denominator;
      if (t > tolerance::kZeroLengthMm && u >= -tolerance::kSegmentParameter && u <= 1 + tolerance::kSegmentParameter)
        nearest = std::min(nearest, t);
    }
    exits[side] = nearest;
  }
  if (!std::isfinite(exits[0]) || !std::isfinite(exits[1])) return std::nullopt;
  return std::array<double, 2>{std::min(exits[0], exits[1]), std::max(exits[0], exits[1])};
}

// The outline of a face's loops: the one enclosing the largest area (a plate's own loops list it
// first, but a face region Clipper gives may list a hole first). `loops` is not empty.
const Loop& outlineOf(const std::vector<Loop>& loops) {
  return *std::max_element(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) {
    return norm(loopNormal(a)) < norm(loopNormal(b));
  });
}

// A sliding dovetail made real: the housing, a rectangle on the face plate's face cut through the
// face layer it enters (as deep as the dovetail, run out past the open end), the two lips that
// overhang the tongue there, and the tongue on the edge plate. The clearance narrows and shortens
// the tongue (the housing keeps its size, so the verified plates and the made ones share it).
struct DovetailPieces {
  Loop housing;
  bool fromFirstFace = true;  // the housing enters the face plate from its first face
  Plate tongue;
  std::vector<Plate> lips;
};

DovetailPieces dovetailPieces(const std::vector<Plate>& plates, const DovetailCut& cut, const JointCutOptions& options,
                              double clearance) {
  const TenonSite& edge = cut.site.edge;
  const DovetailSection d = dovetailSection(plates, edge, options.dovetail);
  const auto [s0, s1] = housingSpan(plates, cut, options.dovetail);
  const double runOut = housingRunOut(plates[edge.mortisePlate], options);
  const double cut0 = cut.openEnd == 0 ? s0 - runOut : s0, cut1 = cut.openEnd == 1 ? s1 + runOut : s1;
  const double low = d.centre - d.wide / 2, high = d.centre + d.wide / 2;
  const double narrowLow = d.centre - d.narrow / 2, narrowHigh = d.centre + d.narrow / 2;
  DovetailPieces pieces;
  pieces.housing = {jointPoint(plates, edge, cut0, low, 0), jointPoint(plates, edge, cut1, low, 0),
                    jointPoint(plates, edge, cut1, high, 0), jointPoint(plates, edge, cut0, high, 0)};
  pieces.fromFirstFace = entersFromFirstFace(plates[edge.mortisePlate], edge.intoMortise);
  pieces.lips = {prismAlongEdge(plates, edge, s0, s1, {{low, 0}, {narrowLow, 0}, {low, d.depth}}),
                 prismAlongEdge(plates, edge, s0, s1, {{narrowHigh, 0}, {high, 0}, {high, d.depth}})};
  const double play = clearance / 2;
  // The tongue runs along the contact only; the housing may run on past it to the open end.
  const double t0 = cut.openEnd == 1 ? s0 + play : edge.from, t1 = cut.openEnd == 0 ? s1 - play : edge.to;
  pieces.tongue = prismAlongEdge(plates, edge, t0, t1,
                                 {{narrowLow + play, 0}, {narrowHigh - play, 0}, {high - play, d.depth - play},
                                  {low + play, d.depth - play}});
  return pieces;
}

class DovetailJointCut final : public JointCut {
 public:
  explicit DovetailJointCut(const DovetailCut& cut) : cut_(cut) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    const int housingPlate = cut_.site.edge.mortisePlate;
    DovetailPieces pieces = dovetailPieces(plates, cut_, options, options.clearance);
    const int face = pieces.fromFirstFace ? 0 : 1;
    cuts.housings[housingPlate][face].push_back(pieces.housing);
    cuts.housingDepth[housingPlate][face] = dovetailSection(plates, cut_.site.edge, options.dovetail).depth;
    for (Plate& lip : pieces.lips) cuts.attached[housingPlate].push_back(std::move(lip));
    cuts.attached[cut_.site.edge.tenonPlate].push_back(std::move(pieces.tongue));
  }

 private:
  DovetailCut cut_;
};

}  // namespace

std::vector<Vec3> DovetailSite::exits() const {
  std::vector<Vec3> ways;
  if (opens[0]) ways.push_back(negated(edge.along));
  if (opens[1]) ways.push_back(edge.along);
  return ways;
}

double housingStop(const std::vector<Plate>& plates, const TenonSite& edge, const DovetailSizes& sizes) {
  return std::max(sizes.stop, plateThickness(plates[edge.mortisePlate]));
}

std::pair<double, double> housingRun(double from, double to, double stop, const std::array<double, 2>& reach,
                                     int openEnd) {
  return openEnd == 1 ? std::make_pair(from + stop, to + reach[1]) : std::make_pair(from - reach[0], to - stop);
}

double housingRunOut(const Plate& facePlate, const JointCutOptions& options) {
  return options.woodMargin + plateThickness(facePlate);
}

bool entersFromFirstFace(const Plate& plate, const Vec3& into) { return dot(into, plateThicknessAxis(plate)) > 0; }

HousingOpenings housingOpenings(const std::vector<Plate>& plates, const TenonSite& edge,
                                std::array<double, 2> strip, double stop, const HousingPlateFace& face,
                                const JointCutOptions& options, bool squareEnds) {
  const Plate& housingPlate = plates[edge.mortisePlate];
  const PlaneFrame frame(housingPlate.bottom[0][0], plateThicknessAxis(housingPlate));
  const double low = strip[0], high = strip[1];  // not a structured binding: C++17 lambdas cannot capture one
  auto rectangle = [&](double s0, double s1) {
    return Loop{jointPoint(plates, edge, s0, low, 0), jointPoint(plates, edge, s1, low, 0),
                jointPoint(plates, edge, s1, high, 0), jointPoint(plates, edge, s0, high, 0)};
  };
  constexpr double kFlush = tolerance::kFlushMm;
  // Open at an end, run on `inside` and `reach` past the contact: the housing from the stop to
  // `inside` lies inside the face plate, and nothing of it lies just beyond `reach` (where a
  // slanted end is left behind).
  auto opensAt = [&](int end, double inside, double reach) {
    const double sign = end == 1 ? 1 : -1, at = (end == 1 ? edge.to : edge.from) + sign * reach;
    const double in = (end == 1 ? edge.to : edge.from) + sign * inside;
    const Loop beyond = rectangle(std::min(at + sign * kFlush, at + sign * options.woodMargin),
                                  std::max(at + sign * kFlush, at + sign * options.woodMargin));
    const Loop housing = end == 1 ? rectangle(edge.from + stop, in - kFlush) : rectangle(in + kFlush, edge.to - stop);
    return areaAgainst({beyond}, face.anywhere, frame, false) < tolerance::kEmptyAreaMm2 &&
           areaAgainst({housing}, face.everywhere, frame, true) < tolerance::kEmptyAreaMm2;
  };
  HousingOpenings openings;
  for (int end = 0; end < 2; ++end) {
    openings.opens[end] = opensAt(end, 0, 0);
    if (openings.opens[end]) continue;
    // Inside the plate where it has material on every layer up to where the strip's first side
    // leaves that, and nothing of it beyond where its last side leaves the plate's outline
    // (the same for a prism; on a plate whose end is bevelled, as a mitre, the slot runs out
    // through the bevel).
    // (No region, as where the layers share no part of the face: no exit through it.)
    auto exitsThrough = [&](const std::vector<Loop>& region) -> std::optional<std::array<double, 2>> {
      if (region.empty()) return std::nullopt;
      return stripExits(plates, edge, outlineOf(region), frame, end, low, high);
    };
    const std::optional<std::array<double, 2>> inner = exitsThrough(face.everywhere);
    const std::optional<std::array<double, 2>> outer = squareEnds ? inner : exitsThrough(face.anywhere);
    if (squareEnds && (!inner || (*inner)[0] <= kFlush || (*inner)[1] - (*inner)[0] > tolerance::kSameExitMm))
      continue;
    if (!squareEnds && (!outer || (*outer)[1] <= kFlush)) continue;
    // (A bevelled end may leave the plate's every-layer part right at the contact's end: no exit
    // past it there.)
    const double inside = inner ? (*inner)[0] : 0;
    const double reach = squareEnds ? inside : (*outer)[1];
    if (opensAt(end, inside, reach)) {
      openings.opens[end] = true;
      openings.reach[end] = reach;
    }
  }
  return openings;
}

std::optional<DovetailSite> dovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                           const JointCutOptions& options) {
  const std::optional<TenonSite> edge = squareEdgeSite(plates, contact, options);
  if (!edge || !isPrism(plates[edge->tenonPlate]) || !isPrism(plates[edge->mortisePlate])) return std::nullopt;
  DovetailSite site;
  site.edge = *edge;
  const Plate& housingPlate = plates[edge->mortisePlate];
  const DovetailSection section = dovetailSection(plates, *edge, options.dovetail);
  if (section.narrow < options.dovetail.narrowestNeck) return std::nullopt;  // too thin a neck to mill
  const double stop = housingStop(plates, *edge, options.dovetail);
  if (edge->to - edge->from < stop + options.shortestJoint) return std::nullopt;
  const HousingOpenings openings =
      housingOpenings(plates, *edge, {section.centre - section.wide / 2, section.centre + section.wide / 2}, stop,
                      {housingPlate.bottom, housingPlate.bottom}, options);
  site.opens = openings.opens;
  site.reach = openings.reach;
  if (!site.opens[0] && !site.opens[1]) return std::nullopt;
  return site;
}

std::vector<Vec3> dovetailFaceNormals(const std::vector<Plate>& plates, const DovetailCut& cut,
                                      const JointCutOptions& options) {
  const TenonSite& edge = cut.site.edge;
  const DovetailSection section = dovetailSection(plates, edge, options.dovetail);
  const double lean = (section.wide - section.narrow) / 2;
  const Vec3 exit = cut.openEnd == 1 ? edge.along : negated(edge.along);
  return {edge.intoMortise,
          normalized(minus(scaled(edge.across, -section.depth), scaled(edge.intoMortise, lean))),
          normalized(minus(scaled(edge.across, section.depth), scaled(edge.intoMortise, lean))), negated(exit)};
}

CutFootprint dovetailFootprint(const std::vector<Plate>& plates, const DovetailCut& cut,
                               const JointCutOptions& options) {
  const DovetailPieces pieces = dovetailPieces(plates, cut, options, 0);
  return {cut.site.edge.mortisePlate, pieces.fromFirstFace ? 1 : 2, pieces.housing};
}

std::shared_ptr<const JointCut> jointCut(const DovetailCut& cut) { return std::make_shared<DovetailJointCut>(cut); }

namespace {

class DovetailFamily final : public JointFamily {
 public:
  explicit DovetailFamily(const JointSetting& setting) : JointFamily(setting) {
    const DovetailSizes& sizes = options().dovetail;
    requireAtLeast(sizes.slope, kLeastFlankSlope, "dovetail.slope");
    requireShare(sizes.depth, "dovetail.depth");
    requireShare(sizes.width, "dovetail.width", true);
    requireAtLeast(sizes.narrowestNeck, 0, "dovetail.narrowestNeck");
    requireAtLeast(sizes.stop, 0, "dovetail.stop");
    for (const PlateContact& contact : graph().computedContacts)
      sites_.push_back(dovetailSiteOf(plates(), contact, options()));
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    const std::optional<DovetailSite>& site = sites_[static_cast<size_t>(contact)];
    return site && exitsLet(site->exits(), site->edge.tenonPlate, mover, d);
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const DovetailCut cut = cutOf(joint);
    std::vector<Vec3> normals = dovetailFaceNormals(plates(), cut, options());
    if (cut.site.edge.tenonPlate != joint.mover) {  // the mover has the housing
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const DovetailCut cut = cutOf(joint);
    footprints.push_back(dovetailFootprint(plates(), cut, options()));
    // The tongue runs along the contact from the stop to the open end: the wood under it.
    const TenonSite& edge = cut.site.edge;
    const auto [start, end] = housingRun(edge.from, edge.to, housingStop(plates(), edge, options().dovetail), {0, 0}, cut.openEnd);
    const Vec3& side = plates()[static_cast<size_t>(edge.tenonPlate)].bottom[0][static_cast<size_t>(edge.edge)];
    footprints.push_back(woodUnderAddedPiece(edge.tenonPlate, side, edge.along, edge.intoMortise, start, end));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(cutOf(joint)));
  }

 private:
  // The dovetail of a planned joint: its housing opens where the tongue plate leaves.
  DovetailCut cutOf(const PlateJoint& joint) const {
    DovetailCut cut;
    cut.site = *sites_[static_cast<size_t>(joint.contact)];
    const Vec3 exit = cut.site.edge.tenonPlate == joint.mover ? joint.direction : negated(joint.direction);
    cut.openEnd = dot(exit, cut.site.edge.along) > 0 ? 1 : 0;
    return cut;
  }
  std::vector<std::optional<DovetailSite>> sites_;  // per contact
};

}  // namespace

std::unique_ptr<JointFamily> makeDovetailFamily(const JointSetting& setting) {
  return std::make_unique<DovetailFamily>(setting);
}

}  // namespace desia
