// SPDX-License-Identifier: GPL-3.0-or-later
// The planar faces of the mesh behind plates-from-mesh (plate.h): its triangles merged
// where their normals agree, each face's plane and its outline of corners and neighbours.
#pragma once

#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/plate.h"
#include "plate/mitred_mesh.h"

namespace desia {
namespace mitred {

// The plane n·x = offset.
struct Plane {
  Vec3 normal;  // unit
  double offset = 0;
};

// A planar face of the mesh: triangles merged across edges where their normals agree.
struct Face {
  std::vector<int> triangles;
  Vec3 normalSum{0, 0, 0};  // area-weighted (twice the area)
  Plane plane;              // outward unit normal; the offset halfway between the extreme vertices
  Vec3 centre{0, 0, 0};     // area-weighted centroid, for messages
  std::vector<int> corners;     // mesh vertices, counter-clockwise from outside, lowest index first
  std::vector<int> sideFace;    // the face across side k (corner k to k+1)
};

// "face 3 (around (x, y, z))": how messages name a face.
std::string faceLabel(const std::vector<Face>& faces, int f);

// The mesh's faces, in the order of their first triangles, each with its plane and outline.
// Throws BadInput naming the face or edge: a face that is not planar within the tolerance or has a
// hole, two neighbours in one plane, a surface folding back onto itself; TooLarge beyond 10000
// faces.
std::vector<Face> meshFaces(const OrientedMesh& oriented, const MitredPlateOptions& options, const std::string& source);

}  // namespace mitred
}  // namespace desia
