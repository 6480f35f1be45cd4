// SPDX-License-Identifier: GPL-3.0-or-later
// The edges of a closed triangle mesh: the checks a union of solids must pass before it replaces
// their shells (every edge in two opposite triangles, the volume kept), and the mending of edges
// where a solid touches itself (four triangles round one edge), for plate_mesh.cpp's plate solids
// and the frames' beams that use them.
#pragma once

#include "desia/model.h"

namespace desia {

// Is every directed edge of the mesh used exactly once, and its reverse exactly once?
bool everyEdgeInTwoOppositeTriangles(const TriangleMesh& mesh);

// Six times the volume the mesh encloses (divergence theorem).
double sixVolume(const TriangleMesh& mesh);

// Gives each pair of triangles that close a wedge of solid around an edge in four triangles an
// edge of its own (the edge split at its middle, one new vertex per pair there), so that every
// edge is in two triangles; where the surface then pinches at a vertex, splitPinchedVertices
// gives each sheet its own copy.
void splitEdgesInFourTriangles(TriangleMesh& mesh);

}  // namespace desia
