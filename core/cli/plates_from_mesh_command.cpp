// SPDX-License-Identifier: GPL-3.0-or-later
// `desia plates-from-mesh`: a closed low-poly mesh (OBJ/STL) to a plate design of mitred plates,
// one per face (core/include/desia/plate.h), written as a `kind: "plate"` document.
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/plate.h"

namespace {

constexpr int kExitBadInput = 2;

const char* kPlatesFromMeshUsage =
    "usage: desia plates-from-mesh --input MESH.obj|.stl --thickness T [--tolerance MM] [--merge-angle DEG]\n"
    "             --output PLATES.json\n";

using desia::cli::UsageError;

// A finite number, the whole text; BadInput naming the flag otherwise (exit 2 like any bad value).
// The core checks the ranges (a thickness the mesh allows, say) and names them.
double numberOption(const std::string& flag, const std::string& text) {
  return desia::cli::numberOption(flag, text, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
}

std::string shortNumber(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

int platesFromMesh(const std::vector<std::string>& args) {
  std::string input, output;
  desia::MitredPlateOptions options;
  bool thicknessGiven = false;
  const desia::cli::Arguments arguments =
      desia::cli::splitArguments(args, {"--input", "--output", "--thickness", "--tolerance", "--merge-angle"});
  if (!arguments.positional.empty()) throw UsageError{"unexpected argument " + arguments.positional[0]};
  for (const auto& [name, value] : arguments.named) {
    if (name == "--input") input = value;
    if (name == "--output") output = value;
    if (name == "--thickness") options.thickness = numberOption(name, value), thicknessGiven = true;
    if (name == "--tolerance") options.tolerance = numberOption(name, value);
    if (name == "--merge-angle") options.mergeAngleDegrees = numberOption(name, value);
  }
  if (input.empty()) throw UsageError{"plates-from-mesh needs --input MESH.obj|.stl"};
  if (!thicknessGiven) throw UsageError{"plates-from-mesh needs --thickness T (millimetres)"};
  if (output.empty() || !desia::cli::hasExtension(output, ".json")) throw UsageError{"plates-from-mesh needs --output PLATES.json"};

  const auto start = std::chrono::steady_clock::now();
  const desia::TriangleMesh mesh = desia::parseMesh(desia::cli::readInputFile(input), input);
  const desia::MitredPlates plates = desia::mitredPlatesFromMesh(mesh, options, input);
  const std::string shape = desia::meshShapeName(input);
  // The document reads the plates back as a design: validated, contacts computed, cut points found.
  const desia::AssemblyDocument document = desia::documentFromPlates(
      plates.plates, desia::PlateOptions{options.tolerance}, input,
      (shape.empty() ? std::string("mesh") : shape) + ": " + std::to_string(plates.plates.size()) + " mitred plates, " +
          shortNumber(options.thickness) + " mm");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The file holds the plates as built, on the nanometre grid; whoever reads it snaps them
  // (regularizedPlates), as `document` here did.
  desia::AssemblyDocument asBuilt = document;
  asBuilt.plates = plates.plates;
  desia::cli::writeOutputFile(output, desia::documentToJson(asBuilt) + "\n");

  std::cout << input << ": " << mesh.triangles.size() << " triangles -> " << plates.plates.size() << " faces, "
            << plates.meshEdges << " edges" << (plates.reoriented ? " (the mesh was inside out: faces turned outward)" : "") << "\n"
            << plates.plates.size() << " mitred plates of " << shortNumber(options.thickness) << " mm, "
            << plates.contacts.size() << " contacts (one per edge)";
  if (plates.largestCornerMismatch > options.tolerance) {
    std::cout << "; where more than 3 faces meet, neighbouring inner corners differ by up to "
              << shortNumber(plates.largestCornerMismatch) << " mm";
  }
  std::cout << "\n";
  if (!document.plateCutPoints.empty()) {
    std::cout << "note: " << document.plateCutPoints.size() << " plate(s) are cut points of the parts-graph (first: plate "
              << document.plates[document.plateCutPoints[0]].id << "); design plate will refuse them\n";
  }
  std::cout << "wrote " << output << " in " << shortNumber(seconds) << " s\n";
  return 0;
}

}  // namespace

int runPlatesFromMeshCommand(const std::vector<std::string>& args) {
  try {
    return platesFromMesh(args);
  } catch (const UsageError& e) {
    std::cerr << "desia: plates-from-mesh: " << e.message << "\n" << kPlatesFromMeshUsage;
    return kExitBadInput;
  }
}
