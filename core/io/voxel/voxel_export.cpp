// SPDX-License-Identifier: GPL-3.0-or-later
// exportAssembly: checks the request, then hands over to the mesh writers or the xmpuzzle writer.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "desia/design_io.h"
#include "io/export_internals.h"
#include "io/kind_entries.h"

namespace desia {
namespace {

constexpr double kMinVoxelSize = 1e-6, kMaxVoxelSize = 1e6;

// Lower bounds of the bytes per triangle, to refuse an oversized export before building it.
int64_t minimumBytesPerTriangle(ExportFormat format) {
  switch (format) {
    case ExportFormat::StlBinary:
    case ExportFormat::StlZip:
    case ExportFormat::BuildPlateStl:
      return 50;
    case ExportFormat::StlAscii:
      return 100;  // facet, loop and three vertex lines with one-digit numbers
    case ExportFormat::Obj:
      return 8;  // "f a b c\n"
    case ExportFormat::XmPuzzle:
      return 0;
  }
  return 0;
}

// Squares of the part surface: voxel faces whose neighbour is not in the same part.
int64_t boundaryFaceCount(const VoxelGrid& grid, const std::vector<int64_t>& voxels) {
  int64_t faces = 0;
  for (const int64_t i : voxels) {
    const Int3 c = grid.coordinates(i);
    const int label = grid.labelAt(i);
    const Int3 neighbours[6] = {{c.x - 1, c.y, c.z}, {c.x + 1, c.y, c.z}, {c.x, c.y - 1, c.z},
                                {c.x, c.y + 1, c.z}, {c.x, c.y, c.z - 1}, {c.x, c.y, c.z + 1}};
    for (const Int3& n : neighbours) faces += !(grid.inside(n.x, n.y, n.z) && grid.label(n.x, n.y, n.z) == label);
  }
  return faces;
}

std::vector<uint8_t> bytesOf(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

std::vector<uint8_t> exportMeshes(const AssemblyDocument& document, ExportFormat format, const ExportOptions& options) {
  const VoxelGrid& grid = document.voxels;
  const std::vector<std::vector<int64_t>> voxels = voxelsByPart(grid);
  const int parts = static_cast<int>(voxels.size()) - 1;
  std::vector<int> chosen;
  for (int part = 1; part <= parts; ++part) {
    if (options.part == 0 || options.part == part) chosen.push_back(part);
  }
  int64_t triangles = 0;
  for (const int part : chosen) {
    if (voxels[part].empty()) throwBadInput(options.source, "part " + std::to_string(part) + " has no voxels");
    triangles += 2 * boundaryFaceCount(grid, voxels[part]);
  }
  if (triangles * minimumBytesPerTriangle(format) > kMaxExportBytes) {
    throwExportTooLarge(
        options.source,
        std::string(exportFormatName(format)) + " file (" + std::to_string(triangles) + " triangles or more)",
        triangles * minimumBytesPerTriangle(format));
  }
  std::vector<NamedMesh> meshes;
  for (const int part : chosen) {
    meshes.push_back({part, insetSurfaceOfVoxels(grid, part, voxels[part], options.voxelSize, options.clearance), ""});
  }

  const std::string what = options.part == 0
                               ? (parts == 1 ? std::string("1 part") : "all " + std::to_string(parts) + " parts")
                               : "part " + std::to_string(options.part) + " of " + std::to_string(parts);
  // The clearance is named only when there is one, so files without it keep their bytes.
  const std::string sizes = "voxel size " + formatNumber(options.voxelSize) +
                            (options.clearance > 0 ? ", clearance " + formatNumber(options.clearance) : "");
  const std::string title = "voxel export, " + what + ", " + sizes;
  std::string bytes;
  switch (format) {
    case ExportFormat::StlZip: {
      // Each file ready to slice: the part turned as on the build plate, resting on z = 0.
      turnFlat(meshes, grid, voxels);
      setDownAtOrigin(meshes);
      std::vector<uint8_t> archive = stlZipArchive(meshes, parts, sizes);
      bytes.assign(archive.begin(), archive.end());
      break;
    }
    case ExportFormat::BuildPlateStl: {
      const double spacing = options.spacing.value_or(options.voxelSize);
      turnFlat(meshes, grid, voxels);
      layOutOnBuildPlate(meshes, spacing);
      bytes = binaryStl(meshes, "build plate, " + what + ", " + sizes + ", spacing " + formatNumber(spacing));
      break;
    }
    case ExportFormat::StlBinary:
      bytes = binaryStl(meshes, title);
      break;
    case ExportFormat::StlAscii:
      bytes = asciiStl(meshes, options.part == 0 ? "assembly" : "part" + std::to_string(options.part));
      break;
    case ExportFormat::Obj:
      bytes = wavefrontObj(meshes, title + "; grid axes kept (+y up as in .puz)");
      break;
    case ExportFormat::XmPuzzle:
      break;
  }
  if (static_cast<int64_t>(bytes.size()) > kMaxExportBytes) {
    throwExportTooLarge(options.source, std::string(exportFormatName(format)) + " file",
                        static_cast<int64_t>(bytes.size()));
  }
  return bytesOf(bytes);
}

}  // namespace

ExportFormat parseExportFormat(const std::string& name) {
  if (name == "stl") return ExportFormat::StlBinary;
  if (name == "stl-ascii") return ExportFormat::StlAscii;
  if (name == "obj") return ExportFormat::Obj;
  if (name == "xmpuzzle") return ExportFormat::XmPuzzle;
  if (name == "stl-zip") return ExportFormat::StlZip;
  if (name == "build-plate-stl") return ExportFormat::BuildPlateStl;
  throwBadInput("", "unknown export format '" + name +
                        "' (expected stl, stl-ascii, obj, xmpuzzle, stl-zip or build-plate-stl)");
}

const char* exportFormatName(ExportFormat format) {
  switch (format) {
    case ExportFormat::StlBinary:
      return "stl";
    case ExportFormat::StlAscii:
      return "stl-ascii";
    case ExportFormat::Obj:
      return "obj";
    case ExportFormat::XmPuzzle:
      return "xmpuzzle";
    case ExportFormat::StlZip:
      return "stl-zip";
    case ExportFormat::BuildPlateStl:
      return "build-plate-stl";
  }
  return "stl";
}

void throwExportTooLarge(const std::string& source, const std::string& what, int64_t bytes) {
  throw Error(ErrorCode::TooLarge, source + ": the " + what + " would be at least " + std::to_string(bytes >> 20) +
                                       " MiB, more than the export limit of " + std::to_string(kMaxExportBytes >> 20) +
                                       " MiB");
}

void requireExportableVoxels(const AssemblyDocument& document, const std::string& source) {
  if (document.kind != AssemblyKind::Voxel) {
    throwBadInput(source, std::string("export needs a voxel assembly, this is a ") + assemblyKindName(document.kind) +
                              " document");
  }
  if (document.voxels.voxelCount() == 0 || document.voxels.maxLabel() == 0) {
    throwBadInput(source, "the assembly is empty: it has no voxels to export");
  }
}

namespace {

// The display form of the export meshes: triangles unshared, each with its face's axis normal.
PartSurface drawableSurface(int partId, const TriangleMesh& mesh) {
  PartSurface surface;
  surface.partId = partId;
  surface.positions.reserve(mesh.triangles.size() * 9);
  surface.normals.reserve(mesh.triangles.size() * 9);
  for (const std::array<int, 3>& triangle : mesh.triangles) {
    const std::array<double, 3>& a = mesh.vertices[triangle[0]];
    const std::array<double, 3>& b = mesh.vertices[triangle[1]];
    const std::array<double, 3>& c = mesh.vertices[triangle[2]];
    // Every triangle lies in a face of a voxel, so its (b - a) x (c - a) has exactly one nonzero
    // component: that axis, with the cross product's sign (CCW from outside = outward), is the normal.
    const double cross[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                             (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                             (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::fabs(cross[k]) > std::fabs(cross[axis])) axis = k;
    }
    float normal[3] = {0.0f, 0.0f, 0.0f};
    normal[axis] = cross[axis] > 0 ? 1.0f : -1.0f;
    for (const std::array<double, 3>* vertex : {&a, &b, &c}) {
      for (int k = 0; k < 3; ++k) {
        surface.positions.push_back(static_cast<float>((*vertex)[k]));
        surface.normals.push_back(normal[k]);
      }
    }
  }
  return surface;
}

}  // namespace

std::vector<PartSurface> partSurfaces(const AssemblyDocument& document, const std::string& source) {
  // Each kind of assembly brings its own surfaces: plates their meshes (in mm), frames their beams
  // and joint pieces, voxels theirs.
  if (document.kind == AssemblyKind::Plate && !document.plates.empty()) return plateFrameEntries().plateSurfaces(document);
  if (isFrameDocument(document)) return plateFrameEntries().frameSurfaces(document, source);
  requireExportableVoxels(document, source);
  const VoxelGrid& grid = document.voxels;
  const std::vector<std::vector<int64_t>> voxels = voxelsByPart(grid);
  const int parts = static_cast<int>(voxels.size()) - 1;
  // Positions and normals: 2 x 9 floats per triangle.
  constexpr int64_t kBytesPerTriangle = 2 * 9 * static_cast<int64_t>(sizeof(float));
  int64_t triangles = 0;
  for (int part = 1; part <= parts; ++part) {
    if (voxels[part].empty()) throwBadInput(source, "part " + std::to_string(part) + " has no voxels");
    triangles += 2 * boundaryFaceCount(grid, voxels[part]);
  }
  if (triangles * kBytesPerTriangle > kMaxExportBytes) {
    throwExportTooLarge(source, "part surfaces (" + std::to_string(triangles) + " triangles or more)",
                        triangles * kBytesPerTriangle);
  }
  std::vector<PartSurface> surfaces;
  surfaces.reserve(static_cast<size_t>(parts));
  for (int part = 1; part <= parts; ++part) {
    surfaces.push_back(drawableSurface(part, surfaceOfVoxels(grid, part, voxels[part], 1.0)));
  }
  return surfaces;
}

std::vector<uint8_t> exportAssembly(const AssemblyDocument& document, ExportFormat format,
                                    const ExportOptions& options) {
  if (document.kind == AssemblyKind::Plate && !document.plates.empty()) {
    return plateFrameEntries().exportPlates(document, format, options);
  }
  requireExportableVoxels(document, options.source);
  const int parts = document.voxels.maxLabel();
  if (options.part < 0 || options.part > parts) {
    throwBadInput(options.source, "part " + std::to_string(options.part) +
                                      " does not exist: the assembly has parts 1 to " + std::to_string(parts) +
                                      " (0 = all parts)");
  }
  if (!(options.voxelSize >= kMinVoxelSize && options.voxelSize <= kMaxVoxelSize)) {
    throwBadInput(options.source,
                  "the voxel size must be a number from 0.000001 to 1000000, got " + formatNumber(options.voxelSize));
  }
  requireValidClearance(options.voxelSize, options.clearance, options.source);
  if (options.spacing && format != ExportFormat::BuildPlateStl) {
    throwBadInput(options.source, std::string("the spacing sets the gaps of a build plate (build-plate-stl), not of ") +
                                      exportFormatName(format));
  }
  if (options.spacing && !(*options.spacing >= 0 && *options.spacing <= kMaxVoxelSize)) {
    throwBadInput(options.source, "the spacing must be a number from 0 to 1000000, got " + formatNumber(*options.spacing));
  }
  if (format != ExportFormat::XmPuzzle) return exportMeshes(document, format, options);
  if (options.clearance != 0) {
    throwBadInput(options.source, "a BurrTools .xmpuzzle holds voxels, not meshes: the clearance applies to stl, "
                                  "stl-ascii, obj, stl-zip and build-plate-stl");
  }
  if (options.part != 0) {
    throwBadInput(options.source, "a BurrTools .xmpuzzle holds the whole puzzle, so it cannot hold only part " +
                                      std::to_string(options.part) + " (choose all parts, part 0)");
  }
  return xmpuzzleFile(document, options.source);
}

}  // namespace desia
