// SPDX-License-Identifier: GPL-3.0-or-later
// Assemblies of closed meshes drawn elsewhere: parts, contacts from their planar faces, verdict
// and plan.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "desia/analysis.h"
#include "desia/model.h"

namespace desia {

// Assemblies of closed triangle meshes drawn elsewhere (a CAD tool, Blender, another kind's export):
// each part a closed, consistently oriented mesh in millimetres; contacts where planar faces of two
// parts lie on each other with opposite normals (paper Section 3.1, as for plates); a disassembly
// plan by translations whose every step is checked by sweeping the moving parts' triangles past the
// parts in place (Section 3.3). Reading the files is io's (desia/formats.h).

namespace mesh {
struct PartGeometry;  // a part's triangles, their boxes and box tree (core/mesh/mesh_geometry.h)
}

struct MeshPart {
  int id = 0;           // the id the user sees (1, 2, ... in reading order)
  std::string name;     // the object, group or solid name, or the file's name
  std::string source;   // the file it came from, for messages
  TriangleMesh mesh;    // millimetres
};

// A curved contact region (a pin in a hole, a ball in a socket): facets of two parts in contact,
// each sharing an edge with another at an angle below tolerance::kCurvedFacetRad. Its contacts are
// those of its planar facets: the curved surface is approximated by them (issue 29's note).
struct CurvedContact {
  int a = 0, b = 0;  // internal indices of the parts
  int facets = 0;    // planar faces of part a in the region
  double area = 0;   // mm², the facets' contact areas
};

struct MeshAssemblyOptions {
  // mm: faces closer than this lie on one another, and parts may overlap by this much. 0 = the
  // default, tolerance::kMeshContactShare of the model's bounding-box diagonal.
  double contactTolerance = 0;
};

struct MeshAssembly {
  std::vector<MeshPart> parts;  // validated: closed, consistently oriented, outward, not overlapping
  double tolerance = 0;         // mm, the contact tolerance in force
  double diagonal = 0;          // mm, of the bounding box of every part
  Assembly assembly;            // parts (same order) and the contacts computed from the faces
  int faceCount = 0;            // planar faces found (coplanar connected triangles), all parts
  std::vector<CurvedContact> curvedContacts;  // in part order
  // Each part's triangles, boxes and box tree, computed once when built and shared by copies.
  std::shared_ptr<const std::vector<mesh::PartGeometry>> geometry;
};

// Validates the parts (BadInput naming the part and an open edge, a flipped triangle, or the two
// parts that overlap and where) and computes their contacts. Throws BadInput for fewer than one part.
MeshAssembly buildMeshAssembly(std::vector<MeshPart> parts, const MeshAssemblyOptions& options = {});

// "" when the parts `moving` (internal indices) translated along the unit vector `d` to infinity
// pass every other part still `present` without entering it (by more than the tolerance); else the
// first part hit, as "part ID". Exact on triangles: each front-facing triangle of the moving parts,
// swept along d (a prism), against each back-facing triangle of the others, pruned by box trees.
std::string meshSweepObstacle(const MeshAssembly& meshes, const std::vector<int>& moving,
                              const std::vector<bool>& present, const Vec3& d);

// A disassembly plan by translations, single parts first (straight out, else by a bent path of up
// to three moves) and groups of parts where no single part can leave, every step checked by the
// sweep (meshSweepObstacle, from the part's place on its path). Groups: the parts a part drags
// along d in the blocking graph of the parts still together. The plan's `moves` list every step
// (`out`), its `removals` the order in which parts come free.
DisassemblyPlan planMeshDisassembly(const MeshAssembly& meshes);

// The check of every kind (DBG and/or LP test on the computed contacts, key and witness) with the
// plan of planMeshDisassembly; shapeRemoval says what was swept.
CheckReport checkMeshAssembly(const MeshAssembly& meshes, const CheckOptions& options = {});

}  // namespace desia
