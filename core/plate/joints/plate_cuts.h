// SPDX-License-Identifier: GPL-3.0-or-later
// Joints made real in the plates (paper Section 5.2, geometry realization): what each joint does
// to the plates it joins, gathered per plate and then cut, and where a joint's cut lies, so that
// the designer can drop a step whose cuts would run into those of an earlier one.
//
// A cut is a 2D boolean on the first face, done by Clipper; each vertex of the result has its
// partner on the second face (straight across, or where a slanted cut's wall or a mitred side
// meets it): a jointed plate is again a Plate that the contact computation, the meshes and the
// exports take as it is.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "desia/plate.h"

namespace desia {

// Where a joint's cut lies in a plate: a region of its face (a loop on or parallel to it), through
// the plate (faces = 3) or into it from its first (1) or second (2) face only. Cuts of different
// joints in one plate must not overlap where they share a face: the designer drops a step whose
// joints would (rather than find it when the whole plan is cut).
// A footprint is a cut (mortises, housings, notches), a slot running out of the outline that a
// plate slides out along (a halved joint's), or the wood under a piece a joint adds to the
// plate's side (a tenon, a dovetail's tongue): the piece would bridge such a slot where it runs
// out through that side, over the crossing plate's way out, so that wood clashes with slots only
// (a mortise beside the side is cut square to the sheet, out of the added piece's way).
enum class FootprintKind { Cut, SlotRunningOut, UnderAddedPiece };

struct CutFootprint {
  int plate = 0;
  int faces = 3;
  Loop region;
  FootprintKind kind = FootprintKind::Cut;
};

// Both in one plate, sharing a face, their regions overlapping inside the plate (more than a
// thousandth of a square millimetre); the wood under an added piece only with a slot running out.
bool footprintsOverlap(const std::vector<Plate>& plates, const CutFootprint& a, const CutFootprint& b);

// The wood under a piece a joint adds to `plate`'s side from `start` to `end` along it (`side`
// is the side's point at 0 on the plate's first face, `along` its unit direction, `outward`
// the unit normal out of the side in the plate's plane): a strip 1 mm deep inside the side (any
// depth finds a slot running out through the side there).
CutFootprint woodUnderAddedPiece(int plate, const Vec3& side, const Vec3& along, const Vec3& outward, double start,
                                 double end);
// The same under a piece standing on a mitre (a mitre tenon, a mitre slide's tongue): `root` on the
// mitre face, `across` the mitre face's direction square to the edge, `outward` its normal out of
// the plate (it leaves the plate's plane). The strip lies inside the mitre's edge on the plate's
// first face, as the other strips (footprints are compared within the first face's outline, which
// a mitre's mid-thickness overhangs or falls short of by half the thickness times its bevel).
CutFootprint woodUnderPieceOnMitre(const std::vector<Plate>& plates, int plate, const Vec3& root, const Vec3& across,
                                   const Vec3& along, const Vec3& outward, double start, double end);

// What the joints do to each plate (indexed as the plates): outlines added to its faces (tenons),
// regions cut through it (mortises, slots, notches), housings cut into it from its first [0] or
// second [1] face as deep as housingDepth says (dovetail housings, blind mortises), regions cut
// through it with slanted walls, and solids
// attached to it (milled pieces: Plate::attached).
struct PlateCuts {
  explicit PlateCuts(size_t plateCount);
  std::vector<std::vector<Loop>> added, removed;
  // Regions cut through it whose walls are slanted to its faces (halved joints of plates crossing
  // at an angle): each its outline on the first face's plane [0] and on the second's [1], vertex
  // for vertex.
  std::vector<std::vector<std::array<Loop, 2>>> slanted;
  std::vector<std::array<std::vector<Loop>, 2>> housings;
  std::vector<std::array<double, 2>> housingDepth;
  std::vector<std::vector<Plate>> attached;
};

// One joint, ready to cut: its family adds what it does to the plates, with `options.clearance`
// mm of play, to `cuts`.
class JointCut {
 public:
  virtual ~JointCut() = default;
  virtual void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const = 0;
};
using JointCutList = std::vector<std::shared_ptr<const JointCut>>;

// The plates with the joints cut into them, in the list's order (the order of each plate's cut
// loops and attached solids in the result: JointFamilies::cuts keeps one order), with
// options.clearance mm of play (each family says where it goes). Throws BadInput naming the plate
// when the cuts split a plate or run into each other.
std::vector<Plate> cutJoints(const std::vector<Plate>& plates, const JointCutList& joints,
                             const JointCutOptions& options);

}  // namespace desia
