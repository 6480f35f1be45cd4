// SPDX-License-Identifier: GPL-3.0-or-later
// Sliding dovetails on plates (milled, JointRealization::Milled; paper Fig. 2, right): where the
// edge's contact runs out of the face plate at an end, a tongue of dovetail section on the edge
// slides in a housing half as deep as the face plate, open at that end and stopped before the
// other, so the edge plate can leave only along the edge, out through the open end. The tongue,
// and the housing's floor and overhanging lips, are prisms along the edge attached to the plates
// (Plate::attached); the housing is cut through the face plate beneath them.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"
#include "plate/joints/tenon.h"

namespace desia {

// Where a sliding dovetail can be milled for one contact: a square edge standing on a face (the
// tenon site's geometry, `edge`) with a way along the edge out of the face plate at one end or
// both: the contact runs out of the face plate there, or the housing can run on past the contact
// through the face plate to its square edge (a stopped housing, as a shelf's in a cabinet side
// that is open at the side's front edge; the CHAIR's rails slide up the legs this way).
struct DovetailSite {
  TenonSite edge;  // tenonPlate: the tongue's plate, mortisePlate: the housing's
  // The housing may open at [0] the contact's start (`from`, towards -along), [1] its end (`to`).
  std::array<bool, 2> opens{false, false};
  // How far the housing runs on past the contact's start [0] / end [1] before it opens (mm; 0
  // where the contact runs out of the face plate).
  std::array<double, 2> reach{0, 0};
  // The directions the tongue plate may leave in: along the edge towards an open end.
  std::vector<Vec3> exits() const;
};

// How far before the contact's closed end a housing stops (wood for the stop): sizes.stop, and
// at least the face plate's thickness.
double housingStop(const std::vector<Plate>& plates, const TenonSite& edge, const DovetailSizes& sizes);

// A housing's run along the edge, from `stop` past the closed end's start of the contact
// [from, to] on to the open end (`openEnd` 1: `to`, 0: `from`), `reach` past the contact there
// (DovetailSite::reach). Cut, it runs out `housingRunOut` further, past the face plate's edge.
std::pair<double, double> housingRun(double from, double to, double stop, const std::array<double, 2>& reach,
                                     int openEnd);
// How far a housing's cut runs on past its open end: the face plate's thickness and the wood
// margin, so that the cutter leaves the plate whole.
double housingRunOut(const Plate& facePlate, const JointCutOptions& options);
// Does a cut going `into` the plate enter it from its first face?
bool entersFromFirstFace(const Plate& plate, const Vec3& into);

// The face plate as a housing sees it along its axis: where it has material on every layer its
// housing runs through (`everywhere`), and on any (`anywhere`); each one outline (the loop of the
// largest area) and its holes, in any order. A
// prism's face outline is both.
struct HousingPlateFace {
  std::vector<Loop> everywhere, anywhere;
};

// Where a housing along `edge` (a strip from `strip`[0] to [1] across edge.across, on the face
// edge.tenonPlate stands on), stopped `stop` before one end of the contact, can open at the
// other: at [0] the contact's start, [1] its end (DovetailSite::opens and reach). Where the
// contact ends inside the face plate, the housing runs on to its edge: with `squareEnds` only
// where both sides of the strip leave it at the same place (a blind housing with a slanted end
// would leave wood in the way or open its side), else to where the later side leaves the plate
// on any layer (a slot cut through, as the slanted sliding dovetail's, runs out past a slanted
// or bevelled end whole).
struct HousingOpenings {
  std::array<bool, 2> opens{false, false};
  std::array<double, 2> reach{0, 0};
};
HousingOpenings housingOpenings(const std::vector<Plate>& plates, const TenonSite& edge, std::array<double, 2> strip,
                                double stop, const HousingPlateFace& face, const JointCutOptions& options,
                                bool squareEnds = true);

// One dovetail to cut: the site and the end its housing opens at (0: from, 1: to).
struct DovetailCut {
  DovetailSite site;
  int openEnd = 1;
};

// The site of a sliding dovetail on `contact`: a square side of one prismatic plate on a face of
// another at right angles, long enough for a stopped housing, the contact running out of the
// face plate at an end; nothing otherwise.
std::optional<DovetailSite> dovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                           const JointCutOptions& options = {});

// The normals of a dovetail's faces, pointing from the tongue plate into the housing plate: the
// shoulder and the housing's floor, the two flanks (leaning back towards the tongue plate, so it
// cannot be pulled out), and the stop at the closed end (against the exit).
std::vector<Vec3> dovetailFaceNormals(const std::vector<Plate>& plates, const DovetailCut& cut,
                                      const JointCutOptions& options);

// The housing, cut into the housing plate from the face the tongue plate stands on.
CutFootprint dovetailFootprint(const std::vector<Plate>& plates, const DovetailCut& cut,
                               const JointCutOptions& options);

// The joint to cut: the housing, its lips and the tongue (narrowed and shortened by the clearance;
// the housing keeps its size, so the verified plates and the made ones share it).
std::shared_ptr<const JointCut> jointCut(const DovetailCut& cut);

// The family for the joint planner (milled joints): a site per contact, a joint where the housing
// can open towards the mover's way out.
std::unique_ptr<JointFamily> makeDovetailFamily(const JointSetting& setting);

}  // namespace desia
