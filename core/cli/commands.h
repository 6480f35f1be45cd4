// SPDX-License-Identifier: GPL-3.0-or-later
// Sub-commands of the desia command line that live in their own files. Each takes the arguments
// after its name and returns the exit status; desia::Error escapes to main (exit 2).
#pragma once

#include <string>
#include <vector>

#include "desia/analysis.h"

// desia voxelize --input MESH.obj|.stl [--resolution R] --output SHAPE.puz|.json
int runVoxelizeCommand(const std::vector<std::string>& args);

// desia design voxel --input SHAPE --parts N [--seed S] [--candidates M] [--rank R] [--mode M]
//   [--min-part-size K] [--groups FILE] [--time-limit S] [--node-limit N] [--key-direction D]
//   --output OUT.puz|OUT.json
int runDesignCommand(const std::vector<std::string>& args);
int runPlateDesignCommand(const std::vector<std::string>& args);  // args[0] == "plate"
// desia design frame --input FRAME.obj|.json|.fpuz [--seed S] [--time-limit S] [--node-limit N] [--joint-size MM] --output RESULT.json
int runFrameDesignCommand(const std::vector<std::string>& args);  // args[0] == "frame"

// desia plates-from-mesh --input MESH.obj|.stl --thickness T [--tolerance MM] [--merge-angle DEG] --output PLATES.json
int runPlatesFromMeshCommand(const std::vector<std::string>& args);

// desia export FILE --format stl|stl-ascii|obj|xmpuzzle [--part N] [--voxel-size S] --output OUT
int runExportCommand(const std::vector<std::string>& args);

// desia check FILE.obj|.stl [more files] [--unit mm|m|inch] [--tolerance MM]: the check of a mesh
// assembly (main.cpp parses the shared check options).
int runMeshCheck(const std::vector<std::string>& files, const desia::CheckOptions& options, bool json,
                 const std::string& unit, double contactTolerance);
