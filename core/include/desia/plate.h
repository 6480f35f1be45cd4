// SPDX-License-Identifier: GPL-3.0-or-later
// Plate structures (paper Section 5.2): flat boards of constant thickness, each given by its two
// parallel faces. Their contacts (which plates touch, where, with which normal) are computed from
// the geometry: a face of one plate lying on a face of another with opposite outward normals and
// an overlap of positive area. That covers a plate's edge face against another plate's face (butt,
// T and L joints) and two plates meeting edge to edge along a shared, possibly mitred, face.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/tolerances.h"
#include "desia/triangle_mesh.h"

namespace desia {

// One closed loop of a face: vertices in order, no closing repeat.
using Loop = std::vector<Vec3>;

struct Plate {
  int id = 0;
  std::string name;
  // The two faces: loop k of `bottom` matches loop k of `top` vertex for vertex; loop 0 is the
  // outline, the others are holes. The plate is the solid between them.
  std::vector<Loop> bottom;
  std::vector<Loop> top;
  // Solids milled as part of this plate where its faces alone cannot hold a joint (a sliding
  // dovetail's tongue on its edge; the floor and overhanging lips of its housing): each a prism
  // of its own, described like a plate (its two end faces), without attachments of its own. The
  // plate is the union of its prism and these; they touch it but are not in contact with it.
  std::vector<Plate> attached;
};

// Newell's normal of a loop: right-handed about the vertex order, its length twice the loop's
// area (robust for non-convex loops).
Vec3 loopNormal(const Loop& loop);

// The unit vector across the plate, from its first face towards its second.
Vec3 plateThicknessAxis(const Plate& plate);

// The outward unit normals of the side faces along loop `loopIndex` (side k joins vertices k, k+1).
std::vector<Vec3> plateSideNormals(const Plate& plate, size_t loopIndex);

// The plate as closed triangle meshes (outward, counter-clockwise seen from outside), in mm: its
// prism and each attached solid a closed shell of its own (they touch). What the swept-collision
// tests run on.
TriangleMesh plateMesh(const Plate& plate);

// The plate as one solid for export and drawing, in mm: its attached solids unioned with it (the
// faces where they touch gone, coplanar faces merged), every edge in exactly two triangles in
// opposite directions, no T-junction, no zero-area triangle, no pinched vertex. Checked as it is
// built (edges and volume); where the check fails, the union triangulated plainly (rows of
// collinear mortises: it may keep zero-area triangles), else the touching shells of plateMesh (a
// few mitre joints' wedges). docs/export.md lists what is left.
TriangleMesh plateSolidMesh(const Plate& plate);

struct PlateOptions {
  // Two faces closer than this (mm) lie on one another; also the planarity tolerance of a face.
  double contactTolerance = tolerance::kContactMm;
};

// A planar contact between two plates (internal indices into the plate list).
struct PlateContact {
  int a = 0, b = 0;
  Vec3 normal{0, 0, 0};         // unit, pointing from plate a into plate b (the outward normal of a's face)
  double area = 0;              // mm^2 of the overlap
  Vec3 edgeDirection{0, 0, 0};  // the shared edge line's direction: where the plates' mid-planes meet
  std::vector<Vec3> region;     // the overlap polygon (largest piece), in 3D
  // Two plates that cross (an X, to be joined by slots: a halved joint, paper Fig. 2) are in the
  // parts-graph with a crossing instead of a face contact: no normal, `edgeDirection` the crossing
  // line, `area` the crossing's area seen across it. See computePlateContacts.
  bool crossing = false;
  Vec3 crossingPoint{0, 0, 0};              // on the crossing line and on both plates' first faces
  double crossingFrom = 0, crossingTo = 0;  // the crossing's extent along the line, from crossingPoint
  // Where a slot may open (the plate's outline ends at the crossing on that side): [0] towards
  // -edgeDirection, [1] towards +edgeDirection; for plate a and plate b.
  std::array<bool, 2> aOpens{false, false}, bOpens{false, false};
};

// Checks every plate (planar faces, positive thickness, parallel matching faces, loops that do not
// cross themselves) and throws BadInput naming the plate and the problem.
void validatePlates(const std::vector<Plate>& plates, const PlateOptions& options, const std::string& source);

// Plates snapped to their design, once, on reading (readers call it after validatePlates): a design
// turned by any rotation or written to 6 decimals (as CAD tools write) has faces meant to be
// parallel 1e-9 to 1e-7 rad apart and faces meant to be square as far off square. Every normal the
// designer and `desia check` derive (contact normals, ways out, joint faces) inherits that noise,
// and the blocking tests decide d·n > tolerance::kDirection (README "Verdicts on computed
// normals"): the noise multiplies the base directions (the MITRED BOX, turned and rounded: 72
// instead of 7) and lets faces block what slides along them. Snapped, every plane of the design is
// exact to rounding (tolerance::kSquaredCosine) and the same design gives the same verdict in any
// turn.
//
// The plates with every face plane (both faces and every side, of the plates and of their attached
// solids) snapped: normals within an angle (below) of parallel made one normal, pairs as close to
// square made square (snappedDirections), each plane through the mean of its vertices, and every
// vertex recomputed as the crossing of its face's plane and its two sides' planes (on their shared
// line where the sides are within tolerance::kStraightSideSine of parallel). A plate whose
// vertices would move further than tolerance::kLargestVertexSnapMm (or the contact tolerance, if
// smaller) is kept as given: a shape no plane fits, which validatePlates judges.
// Drawn: a design from a file or a modelling tool (directions within
// tolerance::kDrawnDirectionRad snapped: a CAD file in metres to 6 decimals). Computed: plates
// desia made or wrote at full precision (the designer's jointed plates, a result's plates; within
// tolerance::kComputedDirectionRad, as finer cuts are real). normal_classes.h.
enum class PlateOrigin { Drawn, Computed };
std::vector<Plate> regularizedPlates(const std::vector<Plate>& plates, const PlateOptions& options, PlateOrigin origin);

// All contacts between the plates, in a fixed order (by plate pair, then faces), and the crossings
// of plates that pass through each other at any angle (each plate's material fills the other's
// thickness over the crossing). Throws BadInput naming both plates when such plates
// overlap only in part (neither a contact nor a crossing explains it).
std::vector<PlateContact> computePlateContacts(const std::vector<Plate>& plates, const PlateOptions& options);

// Throws BadInput when some plate touches nothing or the plates fall into separate groups.
void requireConnectedPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                            const std::string& source);

// Plates from a modelling tool's mesh: every OBJ object or group (`o` / `g`), or every connected
// piece of a mesh without them (STL), is a closed slab whose two largest parallel faces facing
// away from each other are the plate's faces; ids 1, 2, ... in file order, names from the groups.
// Throws BadInput naming the plate when a piece is not such a slab.
std::vector<Plate> platesFromMesh(const TriangleMesh& mesh, const PlateOptions& options, const std::string& source);

// The parts and contacts of the structure (part ids = plate ids), as the interlocking tests read them.
Assembly assemblyFromPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts);

// The plates whose removal disconnects the parts-graph (its cut points). A structure with a cut
// point cannot be interlocking whatever the joints (paper Section 5.2, Fig. 18).
std::vector<int> plateCutPoints(int plateCount, const std::vector<PlateContact>& contacts);

}  // namespace desia
