// SPDX-License-Identifier: GPL-3.0-or-later
// Private pieces of the exports (core/io/*export*.cpp, voxel_surface.cpp, xmpuzzle_format.cpp,
// the gzip and ZIP writers).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/formats.h"
#include "desia/voxel.h"

namespace desia {

// Throws BadInput unless `document` is a voxel assembly with at least one voxel.
void requireExportableVoxels(const AssemblyDocument& document, const std::string& source);
[[noreturn]] void throwExportTooLarge(const std::string& source, const std::string& what, int64_t bytes);

// The rotation of the grid that lays a part flat for printing: one of the 24 proper rotations,
// as a signed permutation (row r of the matrix is sign[r] * e_axis[r]), z up.
struct PrintOrientation {
  std::array<int, 3> axis{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
};
// The most voxels on the lowest layer (the largest face on the plate), then the lowest height,
// then the first of the 24 rotations in a fixed order (identity first).
PrintOrientation printOrientation(const VoxelGrid& grid, const std::vector<int64_t>& voxels);

struct NamedMesh {
  int partId = 0;
  TriangleMesh mesh;
  std::string name;  // the OBJ object's name; "" = "part<partId>"
};

// The parts moved onto a build plate: each part's mesh translated so that its box starts at z = 0
// and at its place in rows along +x (rows stacked along +y, about as long as the plate is deep,
// deepest parts first), `spacing` between the boxes, so no two boxes overlap. Parts keep their
// order in the vector.
void layOutOnBuildPlate(std::vector<NamedMesh>& parts, double spacing);

// Each part turned by its printOrientation (`voxels` as voxelsByPart gives them).
void turnFlat(std::vector<NamedMesh>& parts, const VoxelGrid& grid, const std::vector<std::vector<int64_t>>& voxels);
// Each part moved so that its box starts at the origin (on z = 0, one part per file).
void setDownAtOrigin(std::vector<NamedMesh>& parts);

// A stored ZIP of one binary STL per part, "part-01.stl", ... (as many digits as `partCount`
// needs); `details` goes into each STL's header after "part k of N, ".
std::vector<uint8_t> stlZipArchive(const std::vector<NamedMesh>& parts, int partCount, const std::string& details);

// Mesh writers. `title` goes into the binary STL header and the OBJ comment (plain ASCII).
std::string binaryStl(const std::vector<NamedMesh>& parts, const std::string& title);
std::string asciiStl(const std::vector<NamedMesh>& parts, const std::string& solidName);
std::string wavefrontObj(const std::vector<NamedMesh>& parts, const std::string& title);

// CRC-32 of ISO 3309 / RFC 1952 / ZIP (reflected polynomial 0xEDB88320).
uint32_t crc32(const std::string& data);
// `value`'s low `bytes` bytes, least significant first (gzip and ZIP are little-endian).
void appendLittleEndian(std::vector<uint8_t>& out, uint32_t value, int bytes);

// "%.9g": enough digits for every float and for the voxel-size multiples written here, and
// correctly rounded by both glibc and Emscripten's musl, so text outputs match byte for byte.
std::string formatNumber(double value);

}  // namespace desia
