// SPDX-License-Identifier: GPL-3.0-or-later
// In-plane dovetails (a jigsaw key): two plates lying in ONE plane and meeting edge to edge (the
// hexagons of IBOIS's VDA corner, issue 26) get a dovetail-shaped tab on one plate's side and the
// matching socket in the other, both cut square through the sheet. Seen in the plane the tab
// flares away from its root, so it holds the plates together in every direction of their plane;
// being a prism across the sheet it lets either plate leave only along the sheets' thickness axis,
// both ways (+axis and -axis). A laser or a saw cuts it: a cut joint (paper Section 5.2, geometry
// realization; the plates stay prisms).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "desia/plate.h"
#include "plate/joints/joint_family.h"
#include "plate/joints/plate_cuts.h"

namespace desia {

// Where an in-plane dovetail is cut for one contact (internal plate indices). The tab is drawn in
// the tab plate's first face's plane: its root on the shared side from root0 to root1 (distances
// along `along` from `origin`), its tip `depth` into the socket plate and wider by `flare` on each
// side.
struct InplaneDovetailSite {
  int tabPlate = 0;          // the plate with the tab (the contact's plate a, else b)
  int socketPlate = 0;       // the plate with the socket (the other)
  Vec3 origin{0, 0, 0};      // on the shared side, on the tab plate's first face
  Vec3 intoSocket{0, 0, 0};  // unit: the contact's normal, from the tab plate into the socket plate
  Vec3 along{0, 0, 0};       // unit: along the shared side, in the plane
  Vec3 axis{0, 0, 0};        // unit: the tab plate's thickness axis (both plates': one plane)
  double root0 = 0, root1 = 0;
  double depth = 0;
  double flare = 0;          // how much wider the tip is than the root, on each side
  // The tab grown by `grow` on its flanks and tip, its root run back `back` into the tab plate.
  Loop tab(double grow, double back) const;
  // The directions either plate may leave the other in: +axis and -axis.
  std::vector<Vec3> exits() const;
};

// The site of an in-plane dovetail on `contact`: two prisms whose faces lie in the same two planes,
// meeting edge to edge on square sides over their whole thickness, the tab (sized by
// options.inplaneDovetail) in the middle of the shared side with wood left beside it and its
// socket inside the socket plate with the wood margin all round: the tab on the contact's plate
// a where its socket fits in b, else on b; nothing otherwise. Where plates `crossers` cross both
// (side_crossings.h), "the shared side" is the longest stretch of it they leave free.
std::optional<InplaneDovetailSite> inplaneDovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                                         const JointCutOptions& options = {},
                                                         const std::vector<int>& crossers = {});

// The normals of the joint's faces, from the tab plate into the socket plate: the shoulder and
// tip (the contact's normal) and the two flanks (leaning back towards the tab plate).
std::vector<Vec3> inplaneDovetailFaceNormals(const InplaneDovetailSite& site);

// The socket, through the socket plate (grown by half the clearance).
CutFootprint inplaneDovetailFootprint(const InplaneDovetailSite& site, const JointCutOptions& options);

// The joint to cut: the tab added to the tab plate's outline, the socket (grown by half the
// clearance on the flanks and the tip) cut out of the socket plate's.
std::shared_ptr<const JointCut> jointCut(const InplaneDovetailSite& site);

// The family for the joint planner (cut joints): a site per contact, a joint where the mover
// leaves along the sheets' thickness axis, either way.
std::unique_ptr<JointFamily> makeInplaneDovetailFamily(const JointSetting& setting);

}  // namespace desia
