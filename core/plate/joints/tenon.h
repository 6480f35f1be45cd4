// SPDX-License-Identifier: GPL-3.0-or-later
// Mortise-and-tenon joints on plates (paper Section 5.2, geometry realization; Fig. 2, left): a
// plate's square edge standing on another plate's face at a right angle (T and L joints) gets
// tenons as deep as the other plate is thick.
// - through mortise-and-tenon: the mortises are holes inside the other plate, so the edge plate
//   can leave along its own plane, straight away from the face, and in no other direction;
// - open mortise-and-tenon (a bridle or finger joint): where the edge plate's outer face is flush
//   with the other plate's edge, the mortises are notches open at that edge, so the edge plate can
//   also slide out through the open side.
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

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

// A square side of one prismatic plate standing on a face of another at a right angle, its whole
// thickness on the face: the geometry every edge joint needs (no tenons or housing chosen yet;
// a sliding dovetail's site starts from it too).
std::optional<TenonSite> squareEdgeSite(const std::vector<Plate>& plates, const PlateContact& contact,
                                        const JointCutOptions& options);

// The site of a mortise-and-tenon joint on `contact`, when the geometry allows one: a square side
// of one prismatic plate on a face of another, at right angles, its whole thickness on the face,
// the mortises inside the face plate's outline (through) or open at its edge where the tenon
// plate is flush with it (open); nothing otherwise.
std::optional<TenonSite> tenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                     const JointCutOptions& options = {});

// Where two sites' plates stand on opposite faces of one mortise plate over the same region,
// gives them opposite staggers (see TenonSite::stagger). Sites are per contact, some empty.
void staggerOpposingSites(const std::vector<Plate>& plates, std::vector<std::optional<TenonSite>>* sites);

// The tenons' positions along a site: [start, end) distances from the side's first vertex.
std::vector<std::pair<double, double>> tenonSpans(const std::vector<Plate>& plates, const TenonSite& site,
                                                  const JointCutOptions& options);

// The normals of the joint's faces, from the tenon plate into the mortise plate: the shoulder,
// the tenons' ends (+-along the edge) and their cheeks (+-the tenon plate's thickness axis; none
// on the open side of an open mortise).
std::vector<Vec3> tenonFaceNormals(const TenonSite& site);

// The mortises, through the mortise plate (grown by the clearance), and the wood under the tenons
// on the tenon plate's side (woodUnderAddedPiece).
std::vector<CutFootprint> tenonFootprints(const std::vector<Plate>& plates, const TenonSite& site,
                                          const JointCutOptions& options);

// The joint to cut: the tenons added to the tenon plate's edge, the mortises (grown by half the
// clearance on every side) cut through the mortise plate.
std::shared_ptr<const JointCut> jointCut(const TenonSite& site);

// The family for the joint planner: a site per contact (staggered where two plates stand on
// opposite faces at one place), a joint where the tenons leave along the mover's way out.
std::unique_ptr<JointFamily> makeTenonFamily(const JointSetting& setting);

}  // namespace desia
