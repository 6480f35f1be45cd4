// SPDX-License-Identifier: GPL-3.0-or-later
// Plate sculptures from a low-poly mesh (paper Section 5.2, the LIZARD of Fig. 1): every
// planar face of a closed, consistently oriented mesh becomes a plate of one thickness, inset
// inside the mesh, with mitred edges. The plate's outer face is the mesh face; its inner face lies
// on the face's plane moved inward by the thickness; each side face lies on the plane that bisects
// the dihedral angle between the face and its neighbour across that edge, so two neighbouring
// plates meet edge to edge along one shared mitre face, which computePlateContacts finds.
#pragma once

#include <string>
#include <vector>

#include "desia/triangle_mesh.h"
#include "desia/plate.h"

namespace desia {

struct MitredPlateOptions {
  double thickness = 0;  // mm, > 0: the plates' thickness, measured from the mesh face inward
  // mm: how far a face's vertices may lie off one plane, and the plates' contact tolerance.
  double tolerance = PlateOptions{}.contactTolerance;
  // Adjacent triangles whose normals differ by less than this are one face (a modelling tool's
  // triangulation of a polygon); more than that and they are two plates meeting at a mitre.
  double mergeAngleDegrees = 1.0;
};

struct MitredPlates {
  // One plate per mesh face, ids 1, 2, ... in the order of each face's first triangle in the file
  // (so a rotated copy of the mesh gives the same numbering). `bottom` is the mesh face itself,
  // counter-clockwise seen from outside and starting at its corner with the lowest vertex index;
  // `top` is the inner face, vertex for vertex. No names, no holes.
  std::vector<Plate> plates;
  // Per plate, per side k (the edge from corner k to corner k+1): the plate (index) across it.
  std::vector<std::vector<int>> sideNeighbours;
  // Per plate: the mesh vertices (0-based) at its corners, and the mesh triangles of its face.
  std::vector<std::vector<int>> cornerVertices;
  std::vector<std::vector<int>> faceTriangles;
  // The contacts of the plates (computePlateContacts with the tolerance), each mitre's among them.
  std::vector<PlateContact> contacts;
  int meshEdges = 0;            // edges between two faces (runs of mesh edges); each is one mitre
  bool reoriented = false;      // the mesh was inside out (consistently); its faces were turned outward
  // mm: where more than three faces meet, each plate's inner corner (its inner plane and its two
  // mitres) differs from its neighbours'; the largest such distance (0 when all corners agree).
  double largestCornerMismatch = 0;
};

// The mitred plates of `mesh`. Throws BadInput naming `source` and the face, edge, vertex or value:
// a mesh that is not closed, not manifold (an edge of more than two triangles, a vertex where the
// surface touches itself), inconsistently oriented, in several pieces, or without volume; a face
// that is not planar within the tolerance or has a hole; a thickness that is not positive, or too
// large for a face (its inner face would lose an edge or cross itself; the message gives the
// largest thickness that face allows) or for the shape (an inner corner leaves the mesh).
// TooLarge beyond 10000 faces, or when inner corners x triangles exceed 2e8 (the inside test).
MitredPlates mitredPlatesFromMesh(const TriangleMesh& mesh, const MitredPlateOptions& options, const std::string& source);

}  // namespace desia
