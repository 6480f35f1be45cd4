// SPDX-License-Identifier: GPL-3.0-or-later
// Private pieces of the exports (core/io/*export*.cpp, voxel_surface.cpp, xmpuzzle_format.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/mesh.h"
#include "desia/voxel_grid.h"

namespace desia {

// Throws BadInput unless `document` is a voxel assembly with at least one voxel.
void requireExportableVoxels(const AssemblyDocument& document, const std::string& source);
[[noreturn]] void throwExportTooLarge(const std::string& source, const std::string& what, int64_t bytes);

// Voxel indices of each part, in index order; entry k lists part k (entry 0 stays empty).
std::vector<std::vector<int64_t>> voxelsByPart(const VoxelGrid& grid);

// partSurfaceMesh for voxels already collected (all labelled partId, in index order).
TriangleMesh surfaceOfVoxels(const VoxelGrid& grid, int partId, const std::vector<int64_t>& voxels, double voxelSize);

struct NamedMesh {
  int partId = 0;
  TriangleMesh mesh;
  std::string name;  // the OBJ object's name; "" = "part<partId>"
};

// Mesh writers. `title` goes into the binary STL header and the OBJ comment (plain ASCII).
std::string binaryStl(const std::vector<NamedMesh>& parts, const std::string& title);
std::string asciiStl(const std::vector<NamedMesh>& parts, const std::string& solidName);
std::string wavefrontObj(const std::vector<NamedMesh>& parts, const std::string& title);

// "%.9g": enough digits for every float and for the voxel-size multiples written here, and
// correctly rounded by both glibc and Emscripten's musl, so text outputs match byte for byte.
std::string formatNumber(double value);

}  // namespace desia
