// SPDX-License-Identifier: GPL-3.0-or-later
// Slanted mortise-and-tenon joints (milled; issue 26): the tenon plate S stands with its side
// (bevelled to lie on the face) on a face of the mortise plate F, their planes 60..<90 degrees
// apart by default (slantedTenon.leastDegrees; IBOIS's hexboxes: 80..88). Tenons grow out of that
// side inside S's own slab, along S's plane square to the side, through F, their ends flush with
// F's far face; the mortises through F are slanted: their cheek walls are S's face planes, their
// end walls square to the side. S then
// leaves only along its own plane, straight out of the mortises (the paper's mortise-and-tenon,
// Section 5.2, Fig. 2 left, at an angle; a laser cuts square to the sheet, so only a router makes it).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "analysis/vec3.h"
#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

// A plate's side bevelled to lie on another plate's face (internal plate indices): the site
// every joint on such a side starts from (slanted tenons, slanted sliding dovetails).
struct SlantedSide {
  int tenonPlate = 0;         // S, standing on its side
  int mortisePlate = 0;       // F, whose face it stands on
  int edge = 0;               // S's side on the face (between vertices edge, edge + 1 of its outline)
  Vec3 along{0, 0, 0};        // unit, along that side, from vertex edge to edge + 1
  Vec3 out{0, 0, 0};          // unit, in S's plane, square to the side, into F: S leaves along -out
  Vec3 intoMortise{0, 0, 0};  // unit, F's face normal from S into F (the shoulder's)
  Vec3 across{0, 0, 0};       // unit, S's thickness axis
  // The side's edge on S's first face [0] and second [1] at along = 0 (distances along the side
  // are measured from there on both faces, so that the tenons' ends are square to the side).
  std::array<Vec3, 2> origin{};
  double from = 0, to = 0;  // the stretch of the side on the face, along it
};

// Where a slanted mortise-and-tenon joint can be cut for one contact: the side, and its tenons.
struct SlantedTenonSite : SlantedSide {
  double reach = 0;                              // how far along `out` the tenons run to F's far face
  std::vector<std::pair<double, double>> spans;  // the tenons along the side: [start, end)
};

// The side on `contact` when the geometry has one: S's side lying on F's face (its edges on both
// of S's faces in F's face plane) over its whole thickness and at least options.shortestJoint
// long, their planes from `leastDegrees` (the family's) to less than square apart; nothing
// otherwise.
std::optional<SlantedSide> slantedSideOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                         double leastDegrees, const JointCutOptions& options);

// The site on `contact` when the geometry allows one: a slanted side (slantedSideOf), tenons as
// the square tenon's (tenonWidth, tenonCount, twoTenonsFrom), the mortises inside F's outline on both its faces with
// options.woodMargin of wood round them; nothing otherwise.
std::optional<SlantedTenonSite> slantedTenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                   const JointCutOptions& options = {});

// The tenons, as solids attached to S (first face, second face vertex for vertex).
std::vector<Plate> slantedTenonSolids(const SlantedTenonSite& site);

// The mortises through F: each its outline on F's first face's plane [0] and on its second's [1],
// vertex for vertex, grown by `grow` mm on every side.
std::vector<std::array<Loop, 2>> slantedMortises(const std::vector<Plate>& plates, const SlantedTenonSite& site,
                                                 double grow);

// The normals of the joint's faces, from S into F: the shoulder, the tenons' ends (+-along the
// side) and their cheeks (+-S's thickness axis).
std::vector<Vec3> slantedTenonFaceNormals(const SlantedTenonSite& site);

// Where the mortises lie in F, seen along its axis (both faces' outlines).
std::vector<CutFootprint> slantedTenonFootprints(const std::vector<Plate>& plates, const SlantedTenonSite& site);

// The joint to cut: the tenons attached to S, the mortises (grown by half the clearance on every
// side) cut through F with slanted walls.
std::shared_ptr<const JointCut> jointCut(const SlantedTenonSite& site);

// The family for the joint planner (milled joints).
std::unique_ptr<JointFamily> makeSlantedTenonFamily(const JointSetting& setting);

}  // namespace desia
