// SPDX-License-Identifier: GPL-3.0-or-later
// The joints of a plate structure as cuts in the plates (paper Section 5.2, "geometry realization"),
// and the checks that verify a plan on that jointed geometry.
//
// Joints are made where two-and-a-half-dimensional cuts (a laser or a CNC router cutting through
// the board) can make them: a plate's square edge standing on another plate's face at a right
// angle (T and L joints). The edge gets tenons as deep as the other plate is thick:
// - through mortise-and-tenon: the mortises are holes inside the other plate, so the edge plate
//   can leave along its own plane, straight away from the face, and in no other direction;
// - open mortise-and-tenon (a bridle or finger joint): where the edge plate's outer face is flush
//   with the other plate's edge, the mortises are notches open at that edge, so the edge plate can
//   also slide out through the open side.
// - sliding dovetail (milled, JointRealization::Milled; paper Fig. 2, right): where the edge's
//   contact runs out of the face plate at an end, a tongue of dovetail section on the edge slides
//   in a housing half as deep as the face plate, open at that end and stopped before the other,
//   so the edge plate can leave only along the edge, out through the open end. The tongue, and
//   the housing's floor and overhanging lips, are prisms along the edge attached to the plates
//   (Plate::attached); the housing is cut through the face plate beneath them.
// Every other contact stays an empty joint: the faces only touch.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/plate.h"

namespace desia {

// Where a through mortise-and-tenon joint can be cut for one contact (internal plate indices).
struct TenonSite {
  int tenonPlate = 0;         // the plate standing on its edge (S)
  int mortisePlate = 0;       // the plate whose face it stands on (F)
  int edge = 0;               // the side of the tenon plate's outline (between vertices edge, edge + 1)
  Vec3 intoMortise{0, 0, 0};  // unit: the tenon plate's outward side normal, into the mortise plate
  Vec3 along{0, 0, 0};        // unit: along that side, from vertex edge to edge + 1
  double from = 0, to = 0;    // the part of the side on the face, as distances along it from vertex edge
  // 0: through mortises. +1 or -1: open mortises, the tenon plate's face on that side of its
  // thickness axis flush with the mortise plate's edge.
  int openSide = 0;
  // The directions the tenon plate may leave the mortise plate in (one for through mortises; two,
  // and the ways between them, for open ones).
  std::vector<Vec3> exits() const;
  Vec3 across{0, 0, 0};  // the tenon plate's thickness axis
  // 0: tenons spread along the joint. +1 / -1: two plates stand on opposite faces of the mortise
  // plate at the same place, and their tenons take turns (this one's in the odd quarters or in
  // the others), so their mortises never meet.
  int stagger = 0;
};

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

// A tenon across a mitre (milled; paper Fig. 16a, a mortise-and-tenon for plates that meet at an
// angle with surface contact): two plates meeting edge to edge along a shared mitre face, neither
// face on the other. A tenon of parallelogram section grows out of the tenon plate's mitre face
// along `into`, perpendicular to the shared edge, into a pocket in the other plate that fits it
// on all four sides; the tenon plate can then leave only along -into, straight out of the pocket.
// The tenon and the pocket's surround are prisms along the edge (Plate::attached), and the pocket
// plate gets a notch at its mitre, through it, beneath them.
struct MitreTenon {
  int tenonPlate = 0, pocketPlate = 0;
  Vec3 line{0, 0, 0};     // unit, along the shared edge
  Vec3 into{0, 0, 0};     // unit, perpendicular to the edge, from the tenon plate into the pocket plate
  Vec3 middle{0, 0, 0};   // on the mitre face, the middle of the tenon's root
  Vec3 across{0, 0, 0};   // unit, in the mitre face, perpendicular to the edge
  double halfWidth = 0;   // the tenon's half extent along the edge
  double halfHeight = 0;  // its root's half extent across the edge, in the mitre face
  double depth = 0;       // how far it reaches along `into`
  double notchReach = 0;  // how far the notch runs into the pocket plate from `middle`, past the
                          // pocket and past the mitre (where the plate is whole again)
};

// The tenon across the mitre `contact` for `tenonPlate` leaving the other plate along -into, when
// the other plate is thick enough there to hold its pocket (a millimetre of wood on every side);
// nothing for other contacts or directions.
std::optional<MitreTenon> mitreTenonOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                       int tenonPlate, const Vec3& into);

// The normals of a mitre tenon's faces, from the tenon plate into the pocket plate: its tip, its
// two ends and its two sides (the mitre contact itself stays).
std::vector<Vec3> mitreTenonFaceNormals(const MitreTenon& tenon);

// One dovetail to cut: the site and the end its housing opens at (0: from, 1: to).
struct DovetailCut {
  DovetailSite site;
  int openEnd = 1;
};

// A sliding joint along a mitre (milled; the paper's Fig. 16b, a halved joint for plates that
// meet at an angle with surface contact): the plate leaving along the shared edge (`slidePlate`)
// gets a groove of dovetail section in its mitre face, open towards its end behind it and stopped
// ahead; the other plate carries the tongue that runs in it. The slide plate can then leave only
// along the edge, forwards. The groove is a notch through the slide plate at its mitre with its
// wood given back around the groove (an attached prism) where the plate's other sides are clear;
// between there and its corner behind, the notch leaves the edge cut back (the tongue runs out
// through that gap).
struct MitreSlide {
  int slidePlate = 0, tonguePlate = 0;
  Vec3 line{0, 0, 0};     // unit: the slide plate's way out, along the edge
  Vec3 mitreNormal{0, 0, 0};  // unit: the mitre's normal from the tongue plate into the slide plate
  Vec3 into{0, 0, 0};     // unit: the groove's depth, in the slide plate's plane across the edge (its
                          // faces leave the most wood round the groove that way)
  Vec3 middle{0, 0, 0};   // on the mitre face: where s = 0 along the edge, the tongue's root's middle across
  Vec3 across{0, 0, 0};   // unit, in the mitre face, perpendicular to the edge
  double halfHeight = 0;  // the tongue's root's half extent across the edge
  double depth = 0;       // how far it reaches into the slide plate, along `into`
  double lean = 0;        // how much wider its tip is on each side, per mm of depth (a dovetail)
  double tongueFrom = 0, tongueTo = 0;  // the tongue's extent along the edge; tongueTo is the groove's stop
  double woodFrom = 0;    // where the slide plate's wood around the groove begins again
  double notchFrom = 0;   // the notch's open end, past the slide plate's corner behind
  double notchReach = 0;  // how far the notch runs into the slide plate from the mitre
  Loop notch;             // the cut through the slide plate: the band at the mitre from its stop
                          // back past the whole plate
};

// The slide along the mitre `contact` for `slidePlate` leaving along d (parallel to the shared
// edge), when the plates leave room for the groove and the tongue (a millimetre of wood round the
// groove, a groove at least 10 mm long with wood all round it); nothing otherwise.
std::optional<MitreSlide> mitreSlideOf(const std::vector<Plate>& plates, const PlateContact& contact, int slidePlate,
                                       const Vec3& d);

// The normals of a slide's faces, from the slide plate into the tongue plate: the groove's floor
// (and the mitre), its two flanks, and its stop.
std::vector<Vec3> mitreSlideFaceNormals(const MitreSlide& slide);

// A stub tenon on a lap (milled; two plates lying face to face, as the CHAIR's repair bars on its
// legs): a block on the tenon plate's face, a third of the lap's length and width in its middle,
// standing into a blind mortise as deep as a third of the other plate's thickness (a housing cut
// from that plate's face). The tenon plate can then leave only straight off the lap.
struct FaceTenon {
  int tenonPlate = 0, mortisePlate = 0;
  Vec3 out{0, 0, 0};     // unit: the lap's normal from the mortise plate to the tenon plate (the way out)
  Vec3 origin{0, 0, 0};  // on the lap; the block spans origin + [s0, s1] u + [t0, t1] v
  Vec3 u{0, 0, 0}, v{0, 0, 0};
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
  double depth = 0;      // into the mortise plate
  Loop footprint(double grow) const;  // the block's rectangle on the lap, grown on every side
};

// The stub tenon on the lap `contact` for `tenonPlate` leaving along `d` (straight off the lap,
// both plates prisms, the block inside the lap with a margin); nothing otherwise.
std::optional<FaceTenon> faceTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const Vec3& d);

// The normals of a stub tenon's faces, from the tenon plate into the mortise plate: its end and
// its four sides.
std::vector<Vec3> faceTenonFaceNormals(const FaceTenon& tenon);

struct JointCutOptions {
  double tenonWidth = 0;  // mm along the edge; 0 = from the edge's length (a third, or a fifth for two tenons)
  int tenonCount = 0;     // tenons per joint; 0 = one, or two on edges longer than 8 plate thicknesses
  double clearance = 0;   // mm of play between a tenon and its mortise (the mortise grows by it)
};

// The site of a mortise-and-tenon joint on `contact`, when the geometry allows one: a square side
// of one prismatic plate on a face of another, at right angles, its whole thickness on the face,
// the mortises inside the face plate's outline (through) or open at its edge where the tenon
// plate is flush with it (open); nothing otherwise.
std::optional<TenonSite> tenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                     const JointCutOptions& options = {});

// The site of a sliding dovetail on `contact`: a square side of one prismatic plate on a face of
// another at right angles, long enough for a stopped housing, the contact running out of the
// face plate at an end; nothing otherwise.
std::optional<DovetailSite> dovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact);

// The normals of a dovetail's faces, pointing from the tongue plate into the housing plate: the
// shoulder and the housing's floor, the two flanks (leaning back towards the tongue plate, so it
// cannot be pulled out), and the stop at the closed end (against the exit).
std::vector<Vec3> dovetailFaceNormals(const std::vector<Plate>& plates, const DovetailCut& cut);

// Where two sites' plates stand on opposite faces of one mortise plate over the same region,
// gives them opposite staggers (see TenonSite::stagger). Sites are per contact, some empty.
void staggerOpposingSites(const std::vector<Plate>& plates, std::vector<std::optional<TenonSite>>* sites);

// The tenons' positions along a site: [start, end) distances from the side's first vertex.
std::vector<std::pair<double, double>> tenonSpans(const std::vector<Plate>& plates, const TenonSite& site,
                                                  const JointCutOptions& options);

// The plates with tenons added to the tenon plates' edges and mortises cut through the mortise
// plates, one joint per site, and the slots cut (2D booleans by Clipper on each plate's face, the plates being
// prisms). Throws BadInput naming the plate when the cuts split a plate or run into each other.
// A slot to cut out of a plate (a halved joint's half): a rectangle in its plane, through it.
struct SlotCut {
  int plate = 0;
  Loop rectangle;
};

// The two slots of a halved joint (paper Fig. 2, middle) at a crossing: `mover` leaves along d
// (along the crossing line), so its slot runs from the middle of the crossing back out of its
// outline behind it, and the other plate's from the middle out of its outline ahead; each as wide
// as the other plate is thick plus the clearance.
std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, double clearance);

std::vector<Plate> cutTenonJoints(const std::vector<Plate>& plates, const std::vector<TenonSite>& sites,
                                  const JointCutOptions& options, const std::vector<SlotCut>& slots = {},
                                  const std::vector<DovetailCut>& dovetails = {},
                                  const std::vector<MitreTenon>& mitreTenons = {},
                                  const std::vector<FaceTenon>& faceTenons = {},
                                  const std::vector<MitreSlide>& mitreSlides = {});

// Where a joint's cut lies in a plate: a region of its face (a loop on or parallel to it), through
// the plate (faces = 3) or into it from its first (1) or second (2) face only. Cuts of different
// joints in one plate must not overlap where they share a face: the designer drops a step whose
// joints would (rather than find it when the whole plan is cut).
struct CutFootprint {
  int plate = 0;
  int faces = 3;
  Loop region;
};
std::vector<CutFootprint> tenonFootprints(const std::vector<Plate>& plates, const TenonSite& site,
                                          const JointCutOptions& options);
CutFootprint dovetailFootprint(const std::vector<Plate>& plates, const DovetailCut& cut);
CutFootprint slotFootprint(const SlotCut& slot);
CutFootprint mitreTenonFootprint(const std::vector<Plate>& plates, const MitreTenon& tenon);
CutFootprint faceTenonFootprint(const std::vector<Plate>& plates, const FaceTenon& tenon);
CutFootprint mitreSlideFootprint(const std::vector<Plate>& plates, const MitreSlide& slide);
// Both in one plate, sharing a face, their regions overlapping inside the plate (more than a
// thousandth of a square millimetre).
bool footprintsOverlap(const std::vector<Plate>& plates, const CutFootprint& a, const CutFootprint& b);

// True when `mover`, moved along the unit direction d by any distance, would pass through
// `obstacle` (their interiors meet). Exact for the plates' polyhedra: two surface triangles whose
// shadows along d overlap with positive area, with the obstacle's triangle ahead, mean a collision.
bool plateCollidesAlong(const Plate& mover, const Plate& obstacle, const Vec3& d, double tolerance);
// The same for closed meshes (plateMesh of each plate, made once when many pairs are tested).
bool meshCollidesAlong(const TriangleMesh& mover, const TriangleMesh& obstacle, const Vec3& d, double tolerance);

}  // namespace desia
