// SPDX-License-Identifier: GPL-3.0-or-later
// A mortise-and-tenon joint (paper Section 5.2, geometry realization; Fig. 2, left): the tenon
// plate S stands with a square side on a face of the mortise plate F, S at a right angle to F.
// Tenons grow out of that side, as deep as F is thick; mortises of the same size (plus the
// clearance) go through F, inside it or open at its edge where S is flush with it. The tenons'
// cheeks (normals +-S's thickness axis; one of them for an open mortise) and ends (+-along the
// side) and the shoulder then block every way but out.
#include "plate/joints/tenon.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// Side k of the outline is square: its face stands at a right angle on the plate's faces (a
// plate given by its two faces may have mitred sides elsewhere).
bool sideIsSquare(const Plate& plate, size_t k) {
  const Vec3 lift = scaled(plateThicknessAxis(plate), plateThickness(plate));
  const size_t next = (k + 1) % plate.bottom[0].size();
  return norm(minus(plate.top[0][k], plus(plate.bottom[0][k], lift))) < tolerance::kPrismMm &&
         norm(minus(plate.top[0][next], plus(plate.bottom[0][next], lift))) < tolerance::kPrismMm;
}

// A rectangle on the tenon plate's side: [start, end] along it, [low, high] across the tenon
// plate's thickness, on the face the tenon plate stands on.
Loop footprint(const Plate& tenonPlate, const TenonSite& site, double start, double end, double low, double high) {
  const Vec3 base = tenonPlate.bottom[0][site.edge];
  auto at = [&](double s, double t) { return plus(base, plus(scaled(site.along, s), scaled(site.across, t))); };
  return {at(start, low), at(end, low), at(end, high), at(start, high)};
}

// The mortise of one tenon: its footprint grown by half the clearance, run out past the open edge.
Loop mortiseOf(const std::vector<Plate>& plates, const TenonSite& site, double start, double end,
               const JointCutOptions& options) {
  const Plate& tenonPlate = plates[site.tenonPlate];
  const double width = plateThickness(tenonPlate), grow = options.clearance / 2;
  const double low = site.openSide < 0 ? -options.woodMargin - grow : -grow;
  const double high = site.openSide > 0 ? width + options.woodMargin + grow : width + grow;
  return footprint(tenonPlate, site, start - grow, end + grow, low, high);
}

// The tenon itself, in the tenon plate's plane: out of its side, as deep as the mortise plate.
Loop tenonOf(const std::vector<Plate>& plates, const TenonSite& site, double start, double end) {
  const Vec3 base = plates[site.tenonPlate].bottom[0][site.edge];
  const Vec3 out = scaled(site.intoMortise, plateThickness(plates[site.mortisePlate]));
  // Reaching into the plate, so that the union joins them across rounding (a turned design).
  const Vec3 in = scaled(site.intoMortise, -tolerance::kTenonRootOverlapMm);
  const Vec3 a = plus(base, scaled(site.along, start)), b = plus(base, scaled(site.along, end));
  return {plus(a, in), plus(b, in), plus(b, out), plus(a, out)};
}

// Which kind of mortise fits: through (inside the face plate with a margin all round), open at
// one side (that side of the tenon plate flush with the face plate's edge), or none.
std::optional<int> mortiseKind(const std::vector<Plate>& plates, TenonSite site,
                               const std::vector<std::pair<double, double>>& spans, const JointCutOptions& options) {
  const Plate& tenonPlate = plates[site.tenonPlate];
  const Plate& mortisePlate = plates[site.mortisePlate];
  const PlaneFrame frame(mortisePlate.bottom[0][0], plateThicknessAxis(mortisePlate));
  const double width = plateThickness(tenonPlate), margin = options.woodMargin + options.clearance / 2;
  constexpr double kFlush = tolerance::kFlushMm;
  const std::vector<Loop> whole = faceRegion(mortisePlate, ClipperLib::ctIntersection);
  const std::vector<Loop> any = faceRegion(mortisePlate, ClipperLib::ctUnion);
  auto inside = [&](double low, double high) {
    std::vector<Loop> rects;
    for (const auto& [start, end] : spans)
      rects.push_back(footprint(tenonPlate, site, start - margin, end + margin, low, high));
    return areaAgainst(rects, whole, frame, true) < tolerance::kEmptyAreaMm2;
  };
  auto clearBeyond = [&](double low, double high) {
    std::vector<Loop> rects;
    for (const auto& [start, end] : spans) rects.push_back(footprint(tenonPlate, site, start, end, low, high));
    return areaAgainst(rects, any, frame, false) < tolerance::kEmptyAreaMm2;
  };
  if (inside(-margin, width + margin)) return 0;
  if (inside(-margin, width - kFlush) && clearBeyond(width + kFlush, width + options.woodMargin)) return 1;
  if (inside(kFlush, width + margin) && clearBeyond(-options.woodMargin, -kFlush)) return -1;
  return std::nullopt;
}

class TenonCut final : public JointCut {
 public:
  explicit TenonCut(const TenonSite& site) : site_(site) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    for (const auto& [start, end] : tenonSpans(plates, site_, options)) {
      cuts.added[site_.tenonPlate].push_back(tenonOf(plates, site_, start, end));
      cuts.removed[site_.mortisePlate].push_back(mortiseOf(plates, site_, start, end, options));
    }
  }

 private:
  TenonSite site_;
};

}  // namespace

std::vector<Vec3> TenonSite::exits() const {
  std::vector<Vec3> ways{negated(intoMortise)};
  if (openSide != 0) ways.push_back(scaled(across, openSide));
  return ways;
}

std::vector<std::pair<double, double>> tenonSpans(const std::vector<Plate>& plates, const TenonSite& site,
                                                  const JointCutOptions& options) {
  const double length = site.to - site.from;
  const double thickness = plateThickness(plates[site.tenonPlate]);
  const int count = options.tenonCount > 0 ? options.tenonCount : (length >= options.twoTenonsFrom * thickness ? 2 : 1);
  if (site.stagger != 0) {
    // 4 count + 1 equal pieces; this side's tenons in pieces 1, 5, 9, ... or 3, 7, 11, ...
    const double piece = length / (4 * count + 1);
    const double width = std::min(options.tenonWidth > 0 ? options.tenonWidth : piece, piece);
    if (width < 2 * options.woodMargin) return {};
    // Pieces are counted the same way on both sides: along the edge's canonical direction.
    const bool reversed = dot(site.along, canonicalSign(site.along)) < 0;
    std::vector<std::pair<double, double>> spans;
    for (int j = 0; j < count; ++j) {
      const int index = 4 * j + (site.stagger > 0 ? 1 : 3);
      const double centre = site.from + piece * ((reversed ? 4 * count - index : index) + 0.5);
      spans.push_back({centre - width / 2, centre + width / 2});
    }
    std::sort(spans.begin(), spans.end());
    return spans;
  }
  const double width = options.tenonWidth > 0 ? options.tenonWidth : length / (2 * count + 1);
  const double pitch = length / count;
  // Tenons need room between them and at the ends: a tenon never wider than its share less a gap.
  if (width >= pitch - std::min(pitch / 3, 2 * options.woodMargin)) return {};
  std::vector<std::pair<double, double>> spans;
  for (int j = 0; j < count; ++j) {
    const double centre = site.from + pitch * (j + 0.5);
    spans.push_back({centre - width / 2, centre + width / 2});
  }
  return spans;
}

void staggerOpposingSites(const std::vector<Plate>& plates, std::vector<std::optional<TenonSite>>* sites) {
  auto footprintBox = [&](const TenonSite& site) {
    const Plate& mortisePlate = plates[site.mortisePlate];
    const PlaneFrame frame(mortisePlate.bottom[0][0], plateThicknessAxis(mortisePlate));
    const Loop rect =
        footprint(plates[site.tenonPlate], site, site.from, site.to, 0, plateThickness(plates[site.tenonPlate]));
    std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Vec3& p : rect) {
      const double x = dot(frame.offset(p), frame.u), y = dot(frame.offset(p), frame.v);
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
    return box;
  };
  for (size_t i = 0; i < sites->size(); ++i) {
    for (size_t j = i + 1; j < sites->size(); ++j) {
      std::optional<TenonSite>& a = (*sites)[i];
      std::optional<TenonSite>& b = (*sites)[j];
      if (!a || !b || a->mortisePlate != b->mortisePlate || dot(a->intoMortise, b->intoMortise) > -0.5) continue;
      const std::array<double, 4> p = footprintBox(*a), q = footprintBox(*b);
      if (p[2] <= q[0] + tolerance::kContactMm || q[2] <= p[0] + tolerance::kContactMm ||
          p[3] <= q[1] + tolerance::kContactMm || q[3] <= p[1] + tolerance::kContactMm)
        continue;
      const bool aFromBelow = dot(a->intoMortise, plateThicknessAxis(plates[a->mortisePlate])) > 0;
      a->stagger = aFromBelow ? 1 : -1;
      b->stagger = -a->stagger;
    }
  }
}

// A square side of one prismatic plate standing on a face of another at a right angle, its whole
// thickness on the face: the geometry every edge joint needs (no tenons or housing chosen yet).
std::optional<TenonSite> squareEdgeSite(const std::vector<Plate>& plates, const PlateContact& contact,
                                        const JointCutOptions& options) {
  const Vec3 axisA = plateThicknessAxis(plates[contact.a]), axisB = plateThicknessAxis(plates[contact.b]);
  const bool aOnFace = std::abs(dot(contact.normal, axisA)) > 1 - tolerance::kFacingCosine;
  const bool bOnFace = std::abs(dot(contact.normal, axisB)) > 1 - tolerance::kFacingCosine;
  if (aOnFace == bOnFace || std::abs(dot(axisA, axisB)) > tolerance::kSquareCosine) return std::nullopt;
  // Plates given by two faces may have mitred sides: the edge itself must be square (below), and
  // the other plate is cut only where it is whole (mortiseKind).
  TenonSite site;
  site.tenonPlate = aOnFace ? contact.b : contact.a;
  site.mortisePlate = aOnFace ? contact.a : contact.b;
  site.intoMortise = aOnFace ? negated(contact.normal) : contact.normal;
  const Plate& tenonPlate = plates[site.tenonPlate];
  const Loop& bottom = tenonPlate.bottom[0];
  const std::vector<Vec3> sideNormals = plateSideNormals(tenonPlate, 0);
  site.across = plateThicknessAxis(tenonPlate);
  const Vec3 middle = [&] {
    Vec3 sum{0, 0, 0};
    for (const Vec3& p : contact.region) sum = plus(sum, p);
    return scaled(sum, 1.0 / static_cast<double>(contact.region.size()));
  }();
  for (size_t k = 0; k < bottom.size(); ++k) {
    const size_t next = (k + 1) % bottom.size();
    if (dot(sideNormals[k], site.intoMortise) < 1 - tolerance::kFacingCosine) continue;
    if (std::abs(dot(minus(middle, bottom[k]), site.intoMortise)) > tolerance::kContactMm) continue;
    if (!sideIsSquare(tenonPlate, k)) return std::nullopt;
    site.edge = static_cast<int>(k);
    site.along = normalized(minus(bottom[next], bottom[k]));
    const auto [regionStart, regionEnd] = extentAlong(contact.region, bottom[k], site.along);
    site.from = std::max(0.0, regionStart);
    site.to = std::min(norm(minus(bottom[next], bottom[k])), regionEnd);
    // The whole thickness of S must stand on F, or the tenon would hang beside the mortise.
    const auto [acrossStart, acrossEnd] = extentAlong(contact.region, bottom[k], site.across);
    if (acrossStart > tolerance::kContactMm || acrossEnd < plateThickness(tenonPlate) - tolerance::kContactMm)
      return std::nullopt;
    if (site.to - site.from < options.shortestJoint) return std::nullopt;
    return site;
  }
  return std::nullopt;
}

std::optional<TenonSite> tenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                     const JointCutOptions& options) {
  std::optional<TenonSite> site = squareEdgeSite(plates, contact, options);
  if (!site) return std::nullopt;
  const std::vector<std::pair<double, double>> spans = tenonSpans(plates, *site, options);
  if (spans.empty()) return std::nullopt;
  const std::optional<int> kind = mortiseKind(plates, *site, spans, options);
  if (!kind) return std::nullopt;
  site->openSide = *kind;
  return site;
}

std::vector<Vec3> tenonFaceNormals(const TenonSite& site) {
  std::vector<Vec3> faces{site.intoMortise, site.along, negated(site.along)};
  if (site.openSide <= 0) faces.push_back(site.across);  // a cheek on that side (none where open)
  if (site.openSide >= 0) faces.push_back(negated(site.across));
  return faces;
}

std::vector<CutFootprint> tenonFootprints(const std::vector<Plate>& plates, const TenonSite& site,
                                          const JointCutOptions& options) {
  std::vector<CutFootprint> footprints;
  const Vec3& side = plates[static_cast<size_t>(site.tenonPlate)].bottom[0][static_cast<size_t>(site.edge)];
  for (const auto& [start, end] : tenonSpans(plates, site, options)) {
    footprints.push_back({site.mortisePlate, 3, mortiseOf(plates, site, start, end, options)});
    footprints.push_back(woodUnderAddedPiece(site.tenonPlate, side, site.along, site.intoMortise, start, end));
  }
  return footprints;
}

std::shared_ptr<const JointCut> jointCut(const TenonSite& site) { return std::make_shared<TenonCut>(site); }

namespace {

class TenonFamily final : public JointFamily {
 public:
  explicit TenonFamily(const JointSetting& setting) : JointFamily(setting) {
    requireAtLeast(options().tenonWidth, 0, "tenonWidth");
    requireAtLeast(options().tenonCount, 0, "tenonCount");
    requireAtLeast(options().twoTenonsFrom, 0, "twoTenonsFrom");
    for (const PlateContact& contact : graph().computedContacts)
      sites_.push_back(tenonSiteOf(plates(), contact, options()));
    staggerOpposingSites(plates(), &sites_);
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    const std::optional<TenonSite>& site = sites_[static_cast<size_t>(contact)];
    return site && exitsLet(site->exits(), site->tenonPlate, mover, d);
  }

  // The only ways a tenon joint lets its plates part.
  void addWaysOut(int contact, int, std::vector<Vec3>& ways) const override {
    const std::optional<TenonSite>& site = sites_[static_cast<size_t>(contact)];
    if (site) {
      for (const Vec3& exit : site->exits()) ways.push_back(exit);
    }
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const TenonSite& site = siteOf(joint);
    std::vector<Vec3> normals = tenonFaceNormals(site);
    if (site.tenonPlate != joint.mover) {  // the mover has the mortises
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    for (CutFootprint& footprint : tenonFootprints(plates(), siteOf(joint), options()))
      footprints.push_back(std::move(footprint));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(siteOf(joint)));
  }

 private:
  const TenonSite& siteOf(const PlateJoint& joint) const {
    return letJointSite(sites_[static_cast<size_t>(joint.contact)], "mortise-tenon");
  }
  std::vector<std::optional<TenonSite>> sites_;  // per contact
};

}  // namespace

std::unique_ptr<JointFamily> makeTenonFamily(const JointSetting& setting) {
  return std::make_unique<TenonFamily>(setting);
}

}  // namespace desia
