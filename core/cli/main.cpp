// SPDX-License-Identifier: GPL-3.0-or-later
// The `desia` command line: a thin shell over the core API. Exit codes: 0 success (interlocking),
// 1 a negative verdict, 2 bad input or usage.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_files.h"
#include "commands.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/version.h"

namespace {

constexpr int kExitNegative = 1;
constexpr int kExitBadInput = 2;

const char* kUsage =
    "usage: desia check FILE [--method dbg|lp|both] [--json] [--graphs]\n"
    "       desia check MESH.obj|.stl|.3mf [MORE ...] [--unit mm|m|inch] [--tolerance MM] [--method ...] [--json]\n"
    "       desia voxelize --input MESH.obj|.stl [--resolution R] --output SHAPE.puz|.json\n"
    "       desia design voxel --input SHAPE.puz|.json --parts N --output OUT.puz|.json\n"
    "             [--seed S] [--candidates M] [--rank compactness|x|y|z|-x|-y|-z] [--mode desia|recursive]\n"
    "             [--min-part-size K] [--max-part-size K] [--even-parts] [--jobs N] [--groups FILE]\n"
    "             [--time-limit SECONDS] [--node-limit N] [--key-direction +y]\n"
    "       desia design plate --input DESIGN.json|.obj|.stl --output RESULT.json [--seed S] [--candidates M]\n"
    "             [--time-limit SECONDS] [--node-limit N] [--joints auto|cut|milled|planned] [--clearance MM]\n"
    "             [--tenon-width MM] [--tenon-count N] [--joint-size NAME=VALUE] [--repair REPAIRED.json]\n"
    "       desia design frame --input FRAME.obj|.json|.fpuz --output RESULT.json [--seed S] [--candidates M]\n"
    "             [--time-limit SECONDS] [--node-limit N] [--joint-size MM]\n"
    "       desia plates-from-mesh --input MESH.obj|.stl --thickness T [--tolerance MM] [--merge-angle DEG]\n"
    "             --output PLATES.json\n"
    "       desia export FILE --format stl|stl-ascii|obj|xmpuzzle|stl-zip|build-plate-stl [--part N]\n"
    "             [--voxel-size S] [--clearance MM] [--spacing MM] --output OUT\n"
    "       desia --version | --help\n"
    "\n"
    "check   tests whether the assembly in FILE (.puz voxel puzzle or JSON assembly document)\n"
    "        is interlocking and plans its disassembly. A plate or frame design result's removal plan\n"
    "        is also replayed on the real shapes (cut plates: contacts recomputed, each plate swept;\n"
    "        frames: each beam and its joint voxels swept along its axis).\n"
    "        --method dbg   directional blocking graphs (default; exact for voxel puzzles)\n"
    "        --method lp    linear program (exact for any contact normals; needs GLPK)\n"
    "        --method both  run both and compare\n"
    "        --json         print one JSON object instead of text\n"
    "        --graphs       list every base direction and DBG (by default only up to 128)\n"
    "        OBJ/STL/3MF files are a mesh assembly (docs/meshes.md): one part per OBJ object or group,\n"
    "        per ASCII STL solid, per binary STL or per 3MF build item (in the model's own unit); parts\n"
    "        closed and not overlapping; contacts where faces\n"
    "        lie on each other; every step of the plan swept. --unit: of the files (default mm);\n"
    "        --tolerance MM: faces this close touch (default 1e-5 of the model's diagonal)\n"
    "voxelize fills every voxel whose centre lies inside the closed mesh (OBJ or STL) and writes\n"
    "        the one-part shape; R voxels along the longest side (default 32, at most 1024);\n"
    "        exit 0 when written\n"
    "design  builds an N-part interlocking puzzle from a voxel shape (paper Sections 4, 5.1) and writes\n"
    "        it once the project's own check verified it (part 1 = key); exit 0 written, 1 none found\n"
    "        within the limits (or Ctrl-C), 2 bad input. --jobs N (default: all cores) searches seeds\n"
    "        S..S+N-1 on threads, the first verified puzzle wins and names its seed (--jobs 1 --seed it\n"
    "        gives the same puzzle); --max-part-size / --even-parts (every part within about 20% of\n"
    "        voxels / N) bound the part sizes, reported as min, max and mean\n"
    "design plate designs the joints of a plate structure (paper Section 5.2): key, removal order and\n"
    "        directions, a joint per pair of touching plates, cut into the plates (through and open\n"
    "        mortise-and-tenon, halved where plates cross; --clearance adds play to the mortises of\n"
    "        fabricationPlates); writes the result once both tests and a swept removal of each plate\n"
    "        verified the jointed plates; --joints auto (default): cut joints if a plan exists, else\n"
    "        milled, else the paper's plan, and says which and why; --joints cut: laser or router cuts\n"
    "        only; --joints milled: also sliding dovetails (CNC; STL/OBJ, no cut sheets), for boards\n"
    "        that end flush such as the BOOKSHELF; --joints planned: the paper's graph design alone,\n"
    "        nothing cut; exit 1 when none is found\n"
    "        or the parts-graph has a cut point (named; --repair writes the design with the bars that\n"
    "        bypass it, paper Fig. 18)\n"
    "design frame designs the 3x3x3 voxel joints of a frame (paper Section 5.3): key beam, removal order\n"
    "        and axes, the beam owning each joint voxel; writes the result once the DBG test and the swept\n"
    "        removal verified it; exit 1 when none is found or a beam is a cut point (named)\n"
    "plates-from-mesh makes every planar face of a closed low-poly mesh a plate of thickness T, inset\n"
    "        inside the mesh with mitred edges (neighbours meet along a shared mitre face); writes the plate\n"
    "        design for design plate; exit 0 written, 2 bad mesh or thickness (the face named)\n"
    "export  writes a voxel assembly as closed part meshes (binary or ASCII STL, OBJ with one object\n"
    "        per part; --part N for one part, --voxel-size S scales voxel units), ready to print\n"
    "        (--clearance MM moves the faces between parts in; stl-zip: one STL per part in a ZIP;\n"
    "        build-plate-stl: every part lying flat on z = 0, --spacing MM apart, default a voxel) or\n"
    "        as a BurrTools .xmpuzzle (gzip XML; the whole puzzle, with desia's assembly and its\n"
    "        disassembly as a solution); exit 0 when written. A frame result exports as stl,\n"
    "        stl-ascii, obj (each beam with its joint voxels), fpuz (FrameInterlock), csv (the cut list),\n"
    "        pieces-obj (each beam body and each glued joint piece its own named object, in place) or\n"
    "        joint-pieces-stl (the joint pieces alone, laid out on z = 0 to print and glue)\n"
    "exit    0 interlocking, 1 not interlocking (or deadlocked, or a plate or frame result whose parts\n"
    "        cannot leave their real shapes in the planned order), 2 bad input or usage\n";

struct UsageError {
  std::string message;
};

int runCheck(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  std::string method = "dbg", unit = "mm";
  double contactTolerance = 0;
  bool json = false, allGraphs = false;
  auto value = [&](size_t& i, const char* what) {
    if (i + 1 == args.size()) throw UsageError{args[i] + " needs a value (" + what + ")"};
    return args[++i];
  };
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--json") {
      json = true;
    } else if (args[i] == "--graphs") {
      allGraphs = true;
    } else if (args[i] == "--method") {
      method = value(i, "dbg, lp or both");
    } else if (args[i].rfind("--method=", 0) == 0) {
      method = args[i].substr(9);
    } else if (args[i] == "--unit") {
      unit = value(i, "mm, m or inch");
    } else if (args[i] == "--tolerance") {
      const std::string text = value(i, "a length in mm");
      char* end = nullptr;
      contactTolerance = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(contactTolerance > 0)) {
        throw UsageError{"--tolerance " + text + ": expected a length in mm above 0"};
      }
    } else if (!args[i].empty() && args[i][0] == '-') {
      throw UsageError{"unknown option " + args[i]};
    } else {
      files.push_back(args[i]);
    }
  }
  if (files.empty()) throw UsageError{"check needs a FILE"};
  desia::CheckOptions options;
  options.method = desia::parseCheckMethod(method);
  options.allGraphs = allGraphs;
  bool meshes = false;
  for (const std::string& file : files) meshes = meshes || desia::isMeshAssemblyPath(file);
  if (meshes) return runMeshCheck(files, options, json, unit, contactTolerance);
  if (files.size() > 1) throw UsageError{"check takes one FILE (or several .obj/.stl files), got also " + files[1]};
  if (unit != "mm" || contactTolerance > 0) throw UsageError{"--unit and --tolerance apply to .obj/.stl files only"};
  const std::string& file = files.front();
  const desia::AssemblyDocument document = desia::parseAssemblyText(desia::cli::readInputFile(file), file);
  const desia::CheckReport report = desia::checkDocument(document, options);
  std::cout << (json ? desia::checkReportToJson(document, report) + "\n" : desia::checkReportToText(document, report));
  return desia::checkPassed(report) ? 0 : kExitNegative;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw UsageError{"missing command"};
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (args[0] == "--version") {
      std::cout << "desia " << desia::kVersion << "\n";
      return 0;
    }
    if (args[0] == "check") return runCheck({args.begin() + 1, args.end()});
    if (args[0] == "voxelize") return runVoxelizeCommand({args.begin() + 1, args.end()});
    if (args[0] == "design") return runDesignCommand({args.begin() + 1, args.end()});
    if (args[0] == "plates-from-mesh") return runPlatesFromMeshCommand({args.begin() + 1, args.end()});
    if (args[0] == "export") return runExportCommand({args.begin() + 1, args.end()});
    throw UsageError{"unknown command '" + args[0] + "'"};
  } catch (const UsageError& e) {
    std::cerr << "desia: " << e.message << "\n\n" << kUsage;
    return kExitBadInput;
  } catch (const desia::Error& e) {
    std::cerr << "desia: error: " << e.what() << "\n";
    return e.code() == desia::ErrorCode::Internal ? 3 : kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "desia: error: out of memory\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "desia: internal error: " << e.what() << "\n";
    return 3;
  }
}
