// SPDX-License-Identifier: GPL-3.0-or-later
// `desia voxelize`: a closed OBJ/STL mesh to a one-part voxel shape (.puz or JSON document).
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "desia/document.h"
#include "desia/formats.h"
#include "desia/voxel.h"

namespace {

constexpr int kExitBadInput = 2;

const char* kVoxelizeUsage = "usage: desia voxelize --input MESH.obj|.stl [--resolution R] --output SHAPE.puz|.json\n";

using desia::cli::UsageError;

int parseResolution(const std::string& text) {
  return desia::cli::parseDigits(text, "--resolution needs a positive integer, got '" + text + "'");
}

int voxelize(const std::vector<std::string>& args) {
  std::string input, output;
  desia::VoxelizeOptions options;
  const desia::cli::Arguments arguments = desia::cli::splitArguments(args, {"--input", "--output", "--resolution"});
  if (!arguments.positional.empty()) throw UsageError{"unexpected argument " + arguments.positional[0]};
  for (const auto& [name, value] : arguments.named) {
    if (name == "--input") input = value;
    if (name == "--output") output = value;
    if (name == "--resolution") options.resolution = parseResolution(value);
  }
  if (input.empty()) throw UsageError{"voxelize needs --input MESH.obj|.stl"};
  if (output.empty()) throw UsageError{"voxelize needs --output SHAPE.puz|.json"};
  const bool json = desia::cli::hasExtension(output, ".json");
  if (!json && !desia::cli::hasExtension(output, ".puz")) {
    throw UsageError{"--output must name a .puz or .json file, got '" + output + "'"};
  }

  const desia::TriangleMesh mesh = desia::parseMesh(desia::cli::readInputFile(input), input);
  desia::VoxelGrid grid = desia::voxelizeSolid(mesh, options, input);
  const int64_t filled = grid.labelCounts()[1];
  const std::string sizeText =
      std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " x " + std::to_string(grid.nz());
  const std::string text =
      json ? desia::documentToJson(desia::documentFromVoxels(std::move(grid), desia::meshShapeName(input))) + "\n"
           : desia::formatPuz(grid);
  desia::cli::writeOutputFile(output, text);
  std::cout << input << ": " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles -> grid "
            << sizeText << ", " << filled << " voxels (one part); wrote " << output << "\n";
  return 0;
}

}  // namespace

int runVoxelizeCommand(const std::vector<std::string>& args) {
  try {
    return voxelize(args);
  } catch (const UsageError& e) {
    std::cerr << "desia: voxelize: " << e.message << "\n" << kVoxelizeUsage;
    return kExitBadInput;
  }
}
