// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/mitre_slide.h"

#include <algorithm>
#include <cmath>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/mitre_tenon.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// mm: the shallowest groove tried, whatever mitreSlide.shallowestGroove says (the depths tried
// shrink by a fifth each time: a least of 0 would never end the loop).
constexpr double kShallowestGrooveMm = 0.1;

// The slide seen as a pocket in the slide plate (the tongue plate holding the "tenon"): the frame,
// the inward direction and the wood around the groove are a mitre tenon's.
MitreTenon grooveView(const MitreSlide& slide) {
  MitreTenon view;
  view.tenonPlate = slide.tonguePlate;
  view.pocketPlate = slide.slidePlate;
  view.line = slide.line;
  view.into = slide.into;
  view.middle = slide.middle;
  view.across = slide.across;
  view.halfHeight = slide.halfHeight;
  view.depth = slide.depth;
  view.notchReach = slide.notchReach;
  return view;
}

// The tongue's section (root corners [0], [1] on the mitre, their tips [3], [2]), a dovetail:
// `depth` along `into`, wider at its tip along the root, less `play` all round (the clearance).
std::vector<Flat> slideSection(const MitreSlide& slide, double play) {
  const double ix = dot(slide.into, slide.across), iy = dot(slide.into, slide.mitreNormal);
  const double h = slide.halfHeight - play, d = slide.depth - play;
  const double tip = slide.halfHeight + slide.lean * slide.depth - play;
  return {{-h, 0}, {h, 0}, {d * ix + tip, d * iy}, {d * ix - tip, d * iy}};
}

// The notch through the slide plate, in its plane (MitreSlide::notch).
Loop slideNotch(const std::vector<Plate>&, const MitreSlide& slide) { return slide.notch; }

// A point of the slide plate's plane: s along the edge from the middle, u inward.
Vec3 at0(const MitreSlide& slide, const Vec3& inward, double s, double u) {
  return plus(slide.middle, plus(scaled(slide.line, s), scaled(inward, u)));
}

Plate prismAlongEdge(const MitreTenon& view, const std::vector<Flat>& section, double from, double to) {
  const MitreFrame frame = mitreFrame(view);
  Plate prism;
  Loop first, second;
  for (const Flat& q : section) {
    first.push_back(frame.at(q, from));
    second.push_back(frame.at(q, to));
  }
  prism.bottom = {first};
  prism.top = {second};
  return prism;
}

// Where the slide plate's other sides come within the notch's reach of its mitre, along the edge:
// the nearest such point behind the middle (s < 0) and ahead (s > 0), from both its faces.
std::pair<double, double> cornersAlongEdge(const Plate& plate, const MitreSlide& slide, const Vec3& inward,
                                           double mitreFrom, double mitreTo) {
  double behind = -HUGE_VAL, ahead = HUGE_VAL;
  for (const std::vector<Loop>* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      for (size_t k = 0; k < loop.size(); ++k) {
        const Vec3 a = minus(loop[k], slide.middle), b = minus(loop[(k + 1) % loop.size()], slide.middle);
        const double sa = dot(a, slide.line), sb = dot(b, slide.line), ua = dot(a, inward), ub = dot(b, inward);
        // The mitre's own edges (along the line, between its outer and inner lines) do not count.
        const bool alongLine = std::abs(ua - ub) < tolerance::kParallelSine * (1 + std::abs(sa - sb));
        if (alongLine && ua >= mitreFrom - tolerance::kSamePointMm && ua <= mitreTo + tolerance::kSamePointMm) continue;
        // The part of the edge with u <= notchReach.
        double t0 = 0, t1 = 1;
        if (ua > slide.notchReach && ub > slide.notchReach) continue;
        if (ua > slide.notchReach) t0 = (slide.notchReach - ua) / (ub - ua);
        if (ub > slide.notchReach) t1 = (slide.notchReach - ua) / (ub - ua);
        for (const double t : {t0, t1}) {
          const double sv = sa + t * (sb - sa);
          if (sv < 0) behind = std::max(behind, sv);
          if (sv > 0) ahead = std::min(ahead, sv);
        }
      }
    }
  }
  return {behind, ahead};
}

class MitreSlideCut final : public JointCut {
 public:
  explicit MitreSlideCut(const MitreSlide& slide) : slide_(slide) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    const MitreTenon view = grooveView(slide_);
    cuts.removed[slide_.slidePlate].push_back(slideNotch(plates, slide_));
    cuts.attached[slide_.slidePlate].push_back(prismAlongEdge(
        view, woodAroundPocket(plates, view, slideSection(slide_, 0)), slide_.woodFrom, slide_.tongueTo));
    cuts.attached[slide_.tonguePlate].push_back(prismAlongEdge(view, slideSection(slide_, options.clearance / 2),
                                                               slide_.tongueFrom,
                                                               slide_.tongueTo - options.clearance / 2));
  }

 private:
  MitreSlide slide_;
};

}  // namespace

namespace {

// The slide's frame: its way out `d` itself, and the mitre's normal made square to it (every face
// of the groove but its stop then lies along d to rounding of doubles: the edge and d may differ
// by 1e-9); the groove's depth across the edge in the slide plate. False where the mitre all but
// lies in the plate.
bool setSlideFrame(MitreSlide& slide, const PlateContact& contact, const Plate& plate, const Vec3& d) {
  slide.line = normalized(d);
  const Vec3 normal = contact.a == slide.slidePlate ? negated(contact.normal) : contact.normal;  // tongue -> slide plate
  slide.mitreNormal = normalized(minus(normal, scaled(slide.line, dot(normal, slide.line))));
  slide.across = normalized(cross(slide.mitreNormal, slide.line));
  slide.into = normalized(cross(plateThicknessAxis(plate), slide.line));
  if (dot(slide.into, slide.mitreNormal) < 0) slide.into = negated(slide.into);
  return !(dot(slide.into, slide.mitreNormal) < tolerance::kGlancingCosine);
}

// Does the slide plate hold the groove at slide.depth with the margin of wood on both faces?
bool grooveHeldByFaces(const MitreSlide& slide, const Plate& plate, const JointCutOptions& options) {
  const Vec3 axis = plateThicknessAxis(plate);
  const double thickness = plateThickness(plate);
  for (const Flat& q : slideSection(slide, 0)) {
    const Vec3 point = plus(slide.middle, plus(scaled(slide.across, q[0]), scaled(slide.mitreNormal, q[1])));
    const double height = dot(minus(point, plate.bottom[0][0]), axis);
    if (height < options.woodMargin || height > thickness - options.woodMargin) return false;
  }
  return true;
}

// The side of the loop through which the notch band's inner edge (at notchReach) leaves the plate
// behind the wood round the groove, or -1.
int sideCrossedBehind(const MitreSlide& slide, const Vec3& inward, const Loop& loop) {
  int side = -1;
  double nearest = -HUGE_VAL;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vec3 a = minus(loop[k], slide.middle), b = minus(loop[(k + 1) % loop.size()], slide.middle);
    const double ua = dot(a, inward), ub = dot(b, inward);
    if ((ua - slide.notchReach) * (ub - slide.notchReach) > 0 || ua == ub) continue;
    const double t = (slide.notchReach - ua) / (ub - ua);
    const double sv = dot(a, slide.line) + t * (dot(b, slide.line) - dot(a, slide.line));
    if (sv < slide.woodFrom && sv > nearest) {
      nearest = sv;
      side = static_cast<int>(k);
    }
  }
  return side;
}

// Does the notch cut the slide plate cleanly? Its band's inner edge leaves the plate behind through
// one side on both faces (its wall meets that side: secondFacePartner; where a face's outline turns
// between them, it would not), the plate stays one piece (an outline that comes back to the band
// behind, not convex there, would fall apart), and the notch's end past the mitre lies where the
// plate is whole, so that its cut ends in wood.
bool notchCutsCleanly(const MitreSlide& slide, const Plate& plate, const Vec3& inward, double mitreTo) {
  const int behind = sideCrossedBehind(slide, inward, plate.bottom[0]);
  if (behind != sideCrossedBehind(slide, inward, plate.top[0]) || behind < 0) return false;
  const PlaneFrame planeFrame(plate.bottom[0][0], plateThicknessAxis(plate));
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(plate.bottom, planeFrame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths({slide.notch}, planeFrame), ClipperLib::ptClip, true);
  ClipperLib::PolyTree left;
  clipper.Execute(ClipperLib::ctDifference, left, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
  if (left.ChildCount() != 1) return false;
  auto at = [&](double s, double u) { return plus(slide.middle, plus(scaled(slide.line, s), scaled(inward, u))); };
  const Loop end{at(slide.woodFrom, mitreTo), at(slide.tongueTo, mitreTo), at(slide.tongueTo, slide.notchReach),
                 at(slide.woodFrom, slide.notchReach)};
  return !(areaAgainst({end}, faceRegion(plate, ClipperLib::ctIntersection), planeFrame, true) >
           tolerance::kEmptyAreaMm2);
}

// With slide.depth set: the notch and the groove's extent along the edge. False where the plate
// leaves no groove of the shortest length with wood all round it, or the notch would not cut it
// cleanly (notchCutsCleanly).
bool placeNotch(const std::vector<Plate>& plates, const PlateContact& contact, MitreSlide& slide,
                const JointCutOptions& options) {
  const Plate& plate = plates[slide.slidePlate];
  const MitreSlideSizes& sizes = options.mitreSlide;
  const auto [s0, s1] = extentAlong(contact.region, contact.region[0], slide.line);
  const double halfLength = (s1 - s0) / 2;
  const double thickness = plateThickness(plate);
  // The notch runs past the groove and past the mitre.
  const MitreTenon view = grooveView(slide);
  const Vec3 inward = pocketInward(plates, view);
  const MitreFrame frame = mitreFrame(view);
  double mitreFrom = HUGE_VAL, mitreTo = -HUGE_VAL;  // the mitre's outer and inner lines
  for (const Vec3& p : contact.region) {
    mitreFrom = std::min(mitreFrom, dot(minus(p, slide.middle), inward));
    mitreTo = std::max(mitreTo, dot(minus(p, slide.middle), inward));
  }
  double reach = mitreTo;  // past the groove's section and the mitre
  for (const Flat& q : slideSection(slide, 0)) reach = std::max(reach, dot(minus(frame.at(q, 0), slide.middle), inward));
  slide.notchReach = reach + options.woodMargin;
  // Along the edge: the wood around the groove only where the plate's other sides are clear of the
  // notch; the groove stopped a plate thickness (sizes.stop at least) short of the end ahead.
  const auto [behind, ahead] = cornersAlongEdge(plate, slide, inward, mitreFrom, mitreTo);
  slide.woodFrom = std::max(behind, -halfLength) + options.woodMargin;
  slide.tongueFrom = slide.woodFrom;
  slide.tongueTo = std::min(halfLength - std::max(sizes.stop, thickness), ahead - options.woodMargin);
  if (slide.tongueTo - slide.woodFrom < sizes.shortestGroove) return false;
  // The notch: the band at the mitre from the groove's stop back past all of the plate, out
  // through its side behind the corner (the tongue leaves through it; where the band's inner edge
  // crosses that mitred side, the cut's wall meets it along the edge: secondFacePartner).
  double rearmost = 0;
  for (const std::vector<Loop>* face : {&plate.bottom, &plate.top})
    for (const Loop& loop : *face)
      for (const Vec3& p : loop) rearmost = std::min(rearmost, dot(minus(p, slide.middle), slide.line));
  constexpr double kPastTheRear = 10;  // mm: the notch runs out of the plate behind by this much
  slide.notchFrom = rearmost - kPastTheRear;
  const double out = -2 * (thickness + slide.depth);
  slide.notch = {at0(slide, inward, slide.notchFrom, out), at0(slide, inward, slide.tongueTo, out),
                 at0(slide, inward, slide.tongueTo, slide.notchReach), at0(slide, inward, slide.notchFrom, slide.notchReach)};
  return notchCutsCleanly(slide, plate, inward, mitreTo);
}

}  // namespace

std::optional<MitreSlide> mitreSlideOf(const std::vector<Plate>& plates, const PlateContact& contact, int slidePlate,
                                       const Vec3& d, const JointCutOptions& options) {
  const std::optional<int> partner = touchingPartnerOf(contact, slidePlate);
  // Edge to edge: neither face on the contact (those are T joints and laps).
  if (!partner || contact.region.size() < 3 || facesOnContact(plates, contact) != 0) return std::nullopt;
  MitreSlide slide;
  slide.slidePlate = slidePlate;
  slide.tonguePlate = *partner;
  const Plate& plate = plates[slidePlate];
  const Vec3 edge = normalized(contact.edgeDirection);
  if (std::abs(std::abs(dot(edge, normalized(d))) - 1) > tolerance::kExactCosine)
    return std::nullopt;  // along the edge only
  if (!setSlideFrame(slide, contact, plate, d)) return std::nullopt;
  const auto [s0, s1] = extentAlong(contact.region, contact.region[0], slide.line);
  const auto [x0, x1] = extentAlong(contact.region, contact.region[0], slide.across);
  slide.middle = plus(contact.region[0], plus(scaled(slide.line, (s0 + s1) / 2), scaled(slide.across, (x0 + x1) / 2)));
  const MitreSlideSizes& sizes = options.mitreSlide;
  slide.halfHeight = sizes.height.of(x1 - x0) / 2;
  slide.lean = sizes.slope;
  if (2 * slide.halfHeight < sizes.lowestRoot) return std::nullopt;
  // The deepest groove the faces hold whose notch cuts the plate cleanly: from the plate's
  // thickness down by a fifth at a time. In thin plates a groove as deep as the plate takes its
  // notch past the short sides at the mitre's ends, on one face past one side and on the other
  // past the next (IBOIS's folded plates: 6 mm plates, notches 8 mm in); a shallower one holds
  // as well and cuts cleanly.
  const double shallowest = std::max(sizes.shallowestGroove, kShallowestGrooveMm);  // the loop ends
  for (slide.depth = plateThickness(plate); slide.depth >= shallowest; slide.depth *= 0.8) {
    if (grooveHeldByFaces(slide, plate, options) && placeNotch(plates, contact, slide, options)) return slide;
  }
  return std::nullopt;
}

std::vector<Vec3> mitreSlideFaceNormals(const MitreSlide& slide) {
  // In the section (x along `across`, y along the mitre's normal) the flanks run from the root
  // corners along (ix -+ lean, iy); their normals, from the slide plate into the tongue.
  const double ix = dot(slide.into, slide.across), iy = dot(slide.into, slide.mitreNormal);
  const Vec3 low = normalized(minus(scaled(slide.across, iy), scaled(slide.mitreNormal, ix - slide.lean)));
  const Vec3 high = normalized(plus(scaled(slide.across, -iy), scaled(slide.mitreNormal, ix + slide.lean)));
  return {negated(slide.mitreNormal), low, high, negated(slide.line)};
}

CutFootprint mitreSlideFootprint(const std::vector<Plate>& plates, const MitreSlide& slide) {
  return {slide.slidePlate, 3, slideNotch(plates, slide)};
}

std::shared_ptr<const JointCut> jointCut(const MitreSlide& slide) { return std::make_shared<MitreSlideCut>(slide); }

namespace {

class MitreSlideFamily final : public JointFamily {
 public:
  explicit MitreSlideFamily(const JointSetting& setting) : JointFamily(setting) {
    const MitreSlideSizes& sizes = options().mitreSlide;
    // A groove with straight flanks would let the tongue out across the mitre too.
    requireAtLeast(sizes.slope, kLeastFlankSlope, "mitreSlide.slope");
    requireShare(sizes.height, "mitreSlide.height");
    requireAtLeast(sizes.lowestRoot, 0, "mitreSlide.lowestRoot");
    requireAtLeast(sizes.shallowestGroove, kShallowestGrooveMm, "mitreSlide.shallowestGroove");
    requireAtLeast(sizes.stop, 0, "mitreSlide.stop");
    requireAtLeast(sizes.shortestGroove, 0, "mitreSlide.shortestGroove");
    slides_.resize(graph().contacts.size());
  }

  bool lets(int contact, int mover, const Vec3& d) const override { return slideFor(contact, mover, d) != nullptr; }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    return mitreSlideFaceNormals(slideOf(joint));
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const MitreSlide slide = slideOf(joint);
    footprints.push_back(mitreSlideFootprint(plates(), slide));
    // The tongue stands on the mitre, along the edge: the wood under it.
    footprints.push_back(woodUnderPieceOnMitre(plates(), slide.tonguePlate, slide.middle, slide.across, slide.line,
                                               slide.mitreNormal, slide.tongueFrom, slide.tongueTo));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(slideOf(joint)));
  }

 private:
  // The planner asks the same pair the same way at many nodes, and each answer clips the plates
  // several times (a groove tried at each depth): each is worked out once, per contact, mover
  // and way along the edge (the only ways a slide lets).
  struct Asked {
    int mover = -1;
    bool forwards = false;
    std::optional<MitreSlide> slide;
  };

  const MitreSlide* slideFor(int contact, int mover, const Vec3& d) const {
    const PlateContact& mitre = this->contact(contact);
    if (std::abs(std::abs(dot(normalized(mitre.edgeDirection), normalized(d))) - 1) > tolerance::kExactCosine)
      return nullptr;  // along the edge only (as mitreSlideOf), before the answers kept per way
    const bool forwards = dot(d, mitre.edgeDirection) > 0;
    std::vector<Asked>& asked = slides_[static_cast<size_t>(contact)];
    for (const Asked& answer : asked) {
      if (answer.mover == mover && answer.forwards == forwards) return answer.slide ? &*answer.slide : nullptr;
    }
    asked.push_back({mover, forwards, mitreSlideOf(plates(), mitre, mover, d, options())});
    return asked.back().slide ? &*asked.back().slide : nullptr;
  }

  const MitreSlide& slideOf(const PlateJoint& joint) const {
    const MitreSlide* slide = slideFor(joint.contact, joint.mover, joint.direction);
    if (slide == nullptr) throw Error(ErrorCode::Internal, "a mitre slide joint where no slide fits");
    return *slide;
  }

  // Per contact, the answers so far (at most four: each plate, each way). Filled as the planner
  // asks, on the one thread a design runs on (each design has families of its own).
  mutable std::vector<std::vector<Asked>> slides_;
};

}  // namespace

std::unique_ptr<JointFamily> makeMitreSlideFamily(const JointSetting& setting) {
  return std::make_unique<MitreSlideFamily>(setting);
}

}  // namespace desia
