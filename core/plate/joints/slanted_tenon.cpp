// SPDX-License-Identifier: GPL-3.0-or-later
// A slanted mortise-and-tenon joint (see slanted_tenon.h). In S's plane the tenon is a
// rectangle from the side out to F's far face on each of S's faces; the two rectangles are the
// same one shifted along the side (S's bevelled side runs on each face at a different place), so
// the tenon is a parallelepiped whose cheeks are S's faces and whose ends are square to the side.
// The mortise is where that parallelepiped (grown by half the clearance) passes through F: on
// each of F's face planes the trace of S's slab over the tenon's stretch.
#include "plate/joints/slanted_tenon.h"

#include <algorithm>
#include <cmath>

#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/tenon.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// Height of a point above F's first face, along F's axis.
double heightIn(const Plate& mortisePlate, const Vec3& point) {
  return dot(minus(point, mortisePlate.bottom[0][0]), plateThicknessAxis(mortisePlate));
}

// The point `s` along the side and `h` across S's thickness (0 on its first face) that lies at
// height z in F (0 on F's first face): on S's face plane at h, reached along `out` from the side.
Vec3 pointInMortise(const Plate& mortisePlate, const SlantedTenonSite& site, double s, double h, double z) {
  const Vec3 axis = plateThicknessAxis(mortisePlate);
  const Vec3 onSide = plus(site.origin[0], plus(scaled(site.along, s), scaled(site.across, h)));
  const double r = (z - heightIn(mortisePlate, onSide)) / dot(site.out, axis);
  return plus(onSide, scaled(site.out, r));
}

// Do the side's edges on both of S's faces lie in the plane of F's face through `onFace`, S
// behind it (away from intoMortise)?
bool sideLiesOnFace(const Plate& tenonPlate, size_t k, const Vec3& onFace, const Vec3& intoMortise) {
  const size_t next = (k + 1) % tenonPlate.bottom[0].size();
  for (const Vec3& p :
       {tenonPlate.bottom[0][k], tenonPlate.bottom[0][next], tenonPlate.top[0][k], tenonPlate.top[0][next]}) {
    if (std::abs(dot(minus(p, onFace), intoMortise)) > tolerance::kContactMm) return false;
  }
  for (const Loop& loop : {tenonPlate.bottom[0], tenonPlate.top[0]}) {
    for (const Vec3& p : loop) {
      if (dot(minus(p, onFace), intoMortise) > tolerance::kContactMm) return false;
    }
  }
  return true;
}

// The side k of S's outline as the site's edge: its direction, the way out and the two edges'
// origins; false where the side has no length or its two edges are not parallel.
bool placeOnSide(const Plate& tenonPlate, size_t k, SlantedSide& site) {
  const size_t next = (k + 1) % tenonPlate.bottom[0].size();
  const Vec3 first = minus(tenonPlate.bottom[0][next], tenonPlate.bottom[0][k]);
  const Vec3 second = minus(tenonPlate.top[0][next], tenonPlate.top[0][k]);
  if (norm(first) < tolerance::kZeroLengthMm || norm(second) < tolerance::kZeroLengthMm) return false;
  site.along = normalized(first);
  if (norm(cross(site.along, normalized(second))) > tolerance::kParallelSine) return false;
  site.edge = static_cast<int>(k);
  site.out = normalized(cross(site.along, site.across));
  if (dot(site.out, site.intoMortise) < 0) site.out = negated(site.out);
  const Vec3& topStart = tenonPlate.top[0][k];
  site.origin = {tenonPlate.bottom[0][k],
                 minus(topStart, scaled(site.along, dot(minus(topStart, tenonPlate.bottom[0][k]), site.along)))};
  return true;
}

// The stretch of the side on the face: the contact's extent along it, within both edges; false
// unless the contact covers the side's whole width (from one edge to the other) over it.
bool stretchOnContact(const Plate& tenonPlate, const PlateContact& contact, SlantedSide& site) {
  const size_t k = static_cast<size_t>(site.edge), next = (k + 1) % tenonPlate.bottom[0].size();
  const Vec3& base = site.origin[0];
  const auto [regionStart, regionEnd] = extentAlong(contact.region, base, site.along);
  const double secondStart = dot(minus(tenonPlate.top[0][k], base), site.along);
  const double secondEnd = dot(minus(tenonPlate.top[0][next], base), site.along);
  site.from = std::max({0.0, regionStart, std::min(secondStart, secondEnd)});
  site.to = std::min({norm(minus(tenonPlate.bottom[0][next], base)), regionEnd, std::max(secondStart, secondEnd)});
  const Vec3 width = normalized(cross(site.intoMortise, site.along));
  const auto [acrossStart, acrossEnd] = extentAlong(contact.region, base, width);
  const double edgeOffset = dot(minus(site.origin[1], base), width);
  return acrossStart <= std::min(0.0, edgeOffset) + tolerance::kContactMm &&
         acrossEnd >= std::max(0.0, edgeOffset) - tolerance::kContactMm;
}

// The tenons' spans as the square tenon's along the same stretch.
std::vector<std::pair<double, double>> spansOf(const std::vector<Plate>& plates, const SlantedTenonSite& site,
                                               const JointCutOptions& options) {
  TenonSite square;
  square.tenonPlate = site.tenonPlate;
  square.mortisePlate = site.mortisePlate;
  square.from = site.from;
  square.to = site.to;
  square.along = site.along;
  return tenonSpans(plates, square, options);
}

// Every mortise grown by the wood margin lies inside F where F has its whole thickness.
bool mortisesInside(const std::vector<Plate>& plates, const SlantedTenonSite& site, const JointCutOptions& options) {
  const Plate& mortisePlate = plates[static_cast<size_t>(site.mortisePlate)];
  const PlaneFrame frame(mortisePlate.bottom[0][0], plateThicknessAxis(mortisePlate));
  std::vector<Loop> loops;
  for (const std::array<Loop, 2>& mortise : slantedMortises(plates, site, options.woodMargin + options.clearance / 2)) {
    loops.push_back(mortise[0]);
    loops.push_back(mortise[1]);
  }
  return areaAgainst(loops, faceRegion(mortisePlate, ClipperLib::ctIntersection), frame, true) <
         tolerance::kEmptyAreaMm2;
}

class SlantedTenonCut final : public JointCut {
 public:
  explicit SlantedTenonCut(const SlantedTenonSite& site) : site_(site) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    for (Plate& tenon : slantedTenonSolids(site_)) cuts.attached[site_.tenonPlate].push_back(std::move(tenon));
    for (std::array<Loop, 2>& mortise : slantedMortises(plates, site_, options.clearance / 2))
      cuts.slanted[site_.mortisePlate].push_back(std::move(mortise));
  }

 private:
  SlantedTenonSite site_;
};

}  // namespace

std::optional<SlantedSide> slantedSideOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                         double leastDegrees, const JointCutOptions& options) {
  if (contact.crossing || contact.region.size() < 3 || facesOnContact(plates, contact) != 1) return std::nullopt;
  const Vec3 axisA = plateThicknessAxis(plates[contact.a]), axisB = plateThicknessAxis(plates[contact.b]);
  const bool aOnFace = std::abs(dot(contact.normal, axisA)) > 1 - tolerance::kFacingCosine;
  // Square plates are the square tenon's; flatter than the family's least angle, none.
  const double cosine = std::abs(dot(axisA, axisB));
  if (cosine <= tolerance::kSquareCosine || cosine > std::cos(leastDegrees * M_PI / 180)) return std::nullopt;
  SlantedSide site;
  site.tenonPlate = aOnFace ? contact.b : contact.a;
  site.mortisePlate = aOnFace ? contact.a : contact.b;
  site.intoMortise = aOnFace ? negated(contact.normal) : contact.normal;
  const Plate& tenonPlate = plates[static_cast<size_t>(site.tenonPlate)];
  site.across = plateThicknessAxis(tenonPlate);
  for (size_t k = 0; k < tenonPlate.bottom[0].size(); ++k) {
    if (!sideLiesOnFace(tenonPlate, k, contact.region[0], site.intoMortise)) continue;
    if (!placeOnSide(tenonPlate, k, site) || !stretchOnContact(tenonPlate, contact, site)) return std::nullopt;
    if (site.to - site.from < options.shortestJoint) return std::nullopt;
    return site;
  }
  return std::nullopt;
}

std::optional<SlantedTenonSite> slantedTenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                   const JointCutOptions& options) {
  const std::optional<SlantedSide> side = slantedSideOf(plates, contact, options.slantedTenon.leastDegrees, options);
  if (!side) return std::nullopt;
  SlantedTenonSite site;
  static_cast<SlantedSide&>(site) = *side;
  site.reach = plateThickness(plates[static_cast<size_t>(site.mortisePlate)]) / dot(site.out, site.intoMortise);
  site.spans = spansOf(plates, site, options);
  if (site.spans.empty() || !mortisesInside(plates, site, options)) return std::nullopt;
  return site;
}

std::vector<Plate> slantedTenonSolids(const SlantedTenonSite& site) {
  std::vector<Plate> solids;
  const Vec3 end = scaled(site.out, site.reach);
  for (const auto& [start, stop] : site.spans) {
    std::array<Loop, 2> faces;
    for (size_t f = 0; f < 2; ++f) {
      const Vec3 a = plus(site.origin[f], scaled(site.along, start)),
                 b = plus(site.origin[f], scaled(site.along, stop));
      faces[f] = {a, b, plus(b, end), plus(a, end)};
    }
    solids.push_back(solidOf(faces[0], faces[1]));
  }
  return solids;
}

std::vector<std::array<Loop, 2>> slantedMortises(const std::vector<Plate>& plates, const SlantedTenonSite& site,
                                                 double grow) {
  const Plate& mortisePlate = plates[static_cast<size_t>(site.mortisePlate)];
  const double width = plateThickness(plates[static_cast<size_t>(site.tenonPlate)]);
  const double depth = plateThickness(mortisePlate);
  std::vector<std::array<Loop, 2>> mortises;
  for (const auto& [start, stop] : site.spans) {
    std::array<Loop, 2> faces;
    for (size_t f = 0; f < 2; ++f) {
      const double z = f == 0 ? 0 : depth;
      faces[f] = {pointInMortise(mortisePlate, site, start - grow, -grow, z),
                  pointInMortise(mortisePlate, site, stop + grow, -grow, z),
                  pointInMortise(mortisePlate, site, stop + grow, width + grow, z),
                  pointInMortise(mortisePlate, site, start - grow, width + grow, z)};
    }
    mortises.push_back(std::move(faces));
  }
  return mortises;
}

std::vector<Vec3> slantedTenonFaceNormals(const SlantedTenonSite& site) {
  return {site.intoMortise, site.along, negated(site.along), site.across, negated(site.across)};
}

// Seen along F's axis, a mortise's two outlines are one rectangle shifted square to the side:
// the footprint is the rectangle spanning both, on F's first face.
std::vector<CutFootprint> slantedTenonFootprints(const std::vector<Plate>& plates, const SlantedTenonSite& site) {
  const Plate& mortisePlate = plates[static_cast<size_t>(site.mortisePlate)];
  const Vec3 axis = plateThicknessAxis(mortisePlate);
  const Vec3 width = normalized(cross(axis, site.along));
  std::vector<CutFootprint> footprints;
  for (const std::array<Loop, 2>& mortise : slantedMortises(plates, site, 0)) {
    const Vec3 base = minus(mortise[0][0], scaled(axis, heightIn(mortisePlate, mortise[0][0])));
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (const Loop& face : mortise) {
      for (const Vec3& p : face) {
        low = std::min(low, dot(minus(p, base), width));
        high = std::max(high, dot(minus(p, base), width));
      }
    }
    const double length = dot(minus(mortise[0][1], mortise[0][0]), site.along);
    auto at = [&](double s, double w) { return plus(base, plus(scaled(site.along, s), scaled(width, w))); };
    footprints.push_back({site.mortisePlate, 3, {at(0, low), at(length, low), at(length, high), at(0, high)}});
  }
  return footprints;
}

std::shared_ptr<const JointCut> jointCut(const SlantedTenonSite& site) {
  return std::make_shared<SlantedTenonCut>(site);
}

namespace {

class SlantedTenonFamily final : public JointFamily {
 public:
  explicit SlantedTenonFamily(const JointSetting& setting) : JointFamily(setting) {
    requireAtLeast(options().slantedTenon.leastDegrees, 1, "slantedTenon.leastDegrees");
    for (const PlateContact& contact : graph().computedContacts)
      sites_.push_back(slantedTenonSiteOf(plates(), contact, options()));
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    const std::optional<SlantedTenonSite>& site = sites_[static_cast<size_t>(contact)];
    return site && exitsLet({negated(site->out)}, site->tenonPlate, mover, d);
  }

  // The one way its tenons leave their mortises.
  void addWaysOut(int contact, int, std::vector<Vec3>& ways) const override {
    const std::optional<SlantedTenonSite>& site = sites_[static_cast<size_t>(contact)];
    if (site) ways.push_back(negated(site->out));
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const SlantedTenonSite& site = siteOf(joint);
    std::vector<Vec3> normals = slantedTenonFaceNormals(site);
    if (site.tenonPlate != joint.mover) {  // the mover has the mortises
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const SlantedTenonSite& site = siteOf(joint);
    for (CutFootprint& mortise : slantedTenonFootprints(plates(), site))
      footprints.push_back(std::move(mortise));
    for (const auto& [start, end] : site.spans)
      footprints.push_back(woodUnderAddedPiece(site.tenonPlate, site.origin[0], site.along, site.out, start, end));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(siteOf(joint)));
  }

 private:
  const SlantedTenonSite& siteOf(const PlateJoint& joint) const {
    return letJointSite(sites_[static_cast<size_t>(joint.contact)], "slanted-tenon");
  }
  std::vector<std::optional<SlantedTenonSite>> sites_;  // per contact
};

}  // namespace

std::unique_ptr<JointFamily> makeSlantedTenonFamily(const JointSetting& setting) {
  return std::make_unique<SlantedTenonFamily>(setting);
}

}  // namespace desia
