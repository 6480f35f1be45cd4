// SPDX-License-Identifier: GPL-3.0-or-later
// Every tolerance of the core, named once with its unit and what it decides.
//
// A tolerance says when two computed things count as one (two faces on one another, two
// directions parallel, a motion as no motion). Constants that share a value but not a meaning are
// kept apart (1e-9 mm of length is not a cosine of 1e-9), so that each can change on its own.
// Units: mm (lengths in the design's units, millimetres for plates), mm² (areas), "cosine",
// "sine" or "component" (of unit vectors: dimensionless; a small cosine off square or sine off
// parallel is the angle in radians), rad, "fraction" (relative to the size it is compared with),
// "LP" (the motion programs of the inequality test, where every velocity component is at most 1).
// A tolerance a user may change is an option (PlateOptions::contactTolerance); its default is here.
#pragma once

namespace desia {
namespace tolerance {

// --- Lengths, mm -------------------------------------------------------------------------------

// Default of PlateOptions::contactTolerance: two faces closer than this lie on one another (a
// contact), and a face is planar when its vertices lie this close to one plane. The joint
// geometry and the plate repair measure with this default, not the option.
constexpr double kContactMm = 0.05;
// How far snapping a plate to its design's planes may move a vertex (at most the contact tolerance):
// a file written to a micrometre turns a plane by 1e-7 rad, 1e-4 mm across a 1 m plate.
constexpr double kLargestVertexSnapMm = 0.01;
// A tenon's or housing's side this close to the edge of the plate it enters is flush with it.
constexpr double kFlushMm = 0.01;
// The two sides of a housing strip leave the plate's outline at one place (a square end).
constexpr double kSameExitMm = 0.01;
// How far a tenon reaches back into its own plate, so that their union joins across rounding.
constexpr double kTenonRootOverlapMm = 0.01;
// Points closer than a micrometre are one point (a vertex, a point on an edge or on a line); a
// slant shorter than that is no slant.
constexpr double kSamePointMm = 1e-3;
// Step from a side's middle into the plate to tell its inside from its outside.
constexpr double kInsideProbeMm = 1e-3;
// Two cuts share wood when the region they share is wider than this on average.
constexpr double kLeastSharedWidthMm = 1e-3;
// A top vertex this close to its bottom vertex moved straight across the plate's thickness: the
// side between them stands square on the faces (a plate of such sides is a prism).
constexpr double kPrismMm = 1e-6;
// Coordinates of an exported solid's pieces closer than this are one coordinate: the face planes of
// a frame beam's boxes, the planes and vertices of a plate's body and its attached solids (a mitre
// tenon's corners are computed apart from its plate's, some 1e-5 mm off; Clipper's grid is 1e-4 mm).
constexpr double kMeshWeldMm = 1e-4;
// A plate's exported union with its attached solids may differ in volume from the sum of the
// solids' by this share (the welding of their vertices moves faces by up to kMeshWeldMm); more,
// and the union is not used.
constexpr double kUnionVolumeShare = 1e-6;
// A length below this is none: an edge of no length, a crossing at the point it starts from, a
// part past the usable width of a cut sheet by less.
constexpr double kZeroLengthMm = 1e-9;
// Lengths computed from the same inputs that differ by less than this are equal (rounding of
// doubles on lengths of millimetres to metres): coinciding corners, boxes that only touch.
constexpr double kRoundingMm = 1e-12;

// Fraction of a mesh assembly's bounding-box diagonal: the default contact tolerance of
// MeshAssemblyOptions (faces this close lie on one another; parts may overlap this much). Binary
// STL stores floats (6e-8 relative), and a model rotated or rescaled keeps its faces this flat.
constexpr double kMeshContactShare = 1e-5;

// --- Areas, mm² --------------------------------------------------------------------------------

// Clipper's rounding along a long outline (its 1e-4 mm grid): a difference of outlines this
// small is no wood, far below any joint.
constexpr double kOutlineSliverMm2 = 1e-2;
// Two cuts share wood only when the region they share is larger than this.
constexpr double kLeastSharedAreaMm2 = 1e-3;
// A region of Clipper's results smaller than this is empty (rounding at a corner or an edge).
constexpr double kEmptyAreaMm2 = 1e-6;
// A piece of a cut sheet's flattened outlines (Clipper on a 1e-3 mm grid) this small or smaller
// is rounding at a corner, not an opening between parts.
constexpr double kSheetSliverMm2 = 1e-2;
// Two areas computed for one outline that differ by less than this are equal: of the bounding
// boxes a plate is laid flat in, the first smallest is kept.
constexpr double kSameAreaMm2 = 1e-6;
// A triangle whose shadow has less than this twice-area is seen edge-on.
constexpr double kEdgeOnTwiceAreaMm2 = 1e-9;
// A corner of a face being triangulated whose twice-area (with its two neighbours) is at most this
// is flat: collinear vertices, up to the rounding of the face's 2D frame, make no triangle.
constexpr double kFlatCornerTwiceAreaMm2 = 1e-6;
// A face whose twice-area (the length of its unnormalised normal) is below this has no area.
constexpr double kNoTwiceAreaMm2 = 1e-12;
// A triangle of a written mesh whose twice-area is at most this has no area: robust mesh tools
// call it degenerate (the tests count areas up to 1e-9 mm²).
constexpr double kDegenerateTriangleTwiceAreaMm2 = 2e-9;

// Fraction of the squared bounding-box diagonal of a mesh assembly: a contact region or the
// overlap of two triangles' shadows smaller than this has no area (rounding where faces only meet
// along an edge, or a face seen edge-on).
constexpr double kMeshEmptyAreaShare = 1e-10;

// --- Directions: unit vectors (cosine, sine, component) and angles ------------------------------

// The blocking tolerance: a contact blocks d when d·n exceeds it. For unit vectors in general: a
// component, cosine, sine or triple product below it is zero (square, parallel, coplanar), and a
// component or cosine within it of ±1 is one (along an axis, the same direction). Far below any
// angle a geometry means, far above the rounding of the cross products that produce normals.
// The same slack when a cosine is compared with a bound (45 degrees).
constexpr double kDirection = 1e-9;
// Unitless: a direction's component below this prints as 0 in labels (+x, "(0.9864,0.1644,0)"),
// which show 4 significant digits; labels are for people, the vectors stay exact.
constexpr double kLabelZero = 5e-5;
// A unit vector's component (or a vector's, as a fraction of its largest component) below this
// is rounding residue (1e-16-sized after a rotation or a cross product) and counts as zero.
constexpr double kComponentNoise = 1e-12;
// Directions exact to rounding (snapped, planned, computed from one another): parallel when their
// cosine is within this of ±1 (1.4e-6 rad), square when it is below this; a cosine within this
// of a bound (45 degrees) meets it.
constexpr double kExactCosine = 1e-12;
// Pairs of snapped directions are squared until their cosine is below this (square to rounding).
constexpr double kSquaredCosine = 1e-14;
// Square: |cosine| below this (1e-6 rad off a right angle) is a right angle, as the rounding of a
// design given to a micrometre leaves faces meant to be square.
constexpr double kSquareCosine = 1e-6;
// Parallel: the sine between unit vectors (|a × b|) below this (1e-6 rad) is parallel; so is an
// edge whose slope across a line (rise over run) is below this.
constexpr double kParallelSine = 1e-6;
// Faces whose normals' cosine is within this of 1 (of -1) face the same (the opposite) way:
// about 1.4e-3 rad, for faces of meshes as drawn.
constexpr double kFacingCosine = 1e-6;
// Rad: normals within this angle of parallel (or of square) are made one (square) when snapping
// geometry desia computed; Clipper's grid turns a short cut face by up to 1e-5 rad and is
// recomputed exactly, and finer cuts are real.
constexpr double kComputedDirectionRad = 1e-6;
// Rad: the same for designs drawn elsewhere: a CAD file in metres written to 6 decimals turns the
// side of an 18 mm plate by up to 5.6e-5 rad.
constexpr double kDrawnDirectionRad = 1e-4;
// Rad: faces of a mesh meeting along an edge at less than this (0.5 rad, about 29 degrees) are
// facets of one curved surface (a cylinder of 13 or more sides), not a corner, when noting that a
// curved contact is approximated by its facets (docs/meshes.md).
constexpr double kCurvedFacetRad = 0.5;
// Two Clipper edges crossing at a sine below this are too near parallel to place a point.
constexpr double kEdgeCrossingSine = 1e-3;
// Sine: a plate's side faces this close to parallel (0.01 rad: a straight edge drawn in two
// pieces, a fine curve) are one straight side when snapping its vertices.
constexpr double kStraightSideSine = 1e-2;
// Sine: the edge vectors of one design within about half a degree are parallel (the planned joint
// type: halved along the way out).
constexpr double kPlannedParallelSine = 1e-2;
// Cosine: a way in at less than this to the face it enters (about 87 degrees off its normal) all
// but lies in the plate: no joint.
constexpr double kGlancingCosine = 0.05;

// --- Linear programming (LP units: every velocity component is at most 1) -----------------------

// How far a motion of unit speed may push into a contact and still count as sliding along it:
// far above the residue of computed normals (1e-16), far below anything a geometry means.
constexpr double kPenetration = 1e-12;
// The objective a motion must reach to count as one; relaxation alone reaches about kPenetration
// times the contact count.
constexpr double kMotion = 1e-6;
// A velocity component the simplex returns below this is zero.
constexpr double kVelocityNoise = 1e-9;
// Fraction: parts slower than this fraction of the fastest only creep by the tolerated
// penetration and do not take part in a motion.
constexpr double kMovingSpeedFraction = 1e-3;
// Moving parts whose unit velocities differ by less than this move along one direction.
constexpr double kSameVelocityDirection = 1e-6;
// Relative size under which the cone search of a one-part program (motion_certificates.cpp) takes
// a cross product or determinant as zero, two unit rows as one direction, and a multiplier that
// rounding made slightly negative as zero; the dual bound checks whatever it proposes.
constexpr double kConeSingular = 1e-12;

// --- Voxels and frames ----------------------------------------------------------------------------

// Voxels: a joint whose position lies this close to a whole number of voxels lies on the grid
// (positions are read from decimal text), and a beam's end coordinates this close are equal.
constexpr double kOnGridVoxels = 1e-6;
// Voxels: a side's voxel count is rounded up only past this (0.1 * 3 / 0.1 is not exactly 3).
constexpr double kVoxelCountRounding = 1e-9;
// Fraction: a beam's tangent whose two largest components differ by less than this fraction
// leaves between two faces of the joint cube (no face is nearer).
constexpr double kTieFraction = 1e-6;

// --- Numeric guards (relative) ---------------------------------------------------------------------

// Fraction: lengths and volumes computed from decimal input equal to within this fraction of
// their size are equal (a section of exactly the voxel size, cubes that only touch, a mesh of no
// volume).
constexpr double kRelativeRounding = 1e-9;
// Fraction: a product of two lengths (an area, a 2D cross product) within this fraction of the
// product of their sizes is zero.
constexpr double kProductRounding = 1e-12;
// Fraction of a segment: a crossing within this of its ends lies on it.
constexpr double kSegmentParameter = 1e-9;
// A divisor below this counts as zero (the lines do not cross, the motion does not move along the
// axis): dividing by it would only magnify rounding.
constexpr double kZeroDivisor = 1e-12;

}  // namespace tolerance
}  // namespace desia
