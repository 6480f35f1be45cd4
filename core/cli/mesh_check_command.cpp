// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check FILE.obj|.stl [more files]`: a mesh assembly read, validated, its contacts
// computed, checked and taken apart by swept translations (docs/meshes.md).
#include <iostream>

#include "cli_files.h"
#include "commands.h"
#include "desia/document.h"
#include "desia/formats.h"

int runMeshCheck(const std::vector<std::string>& files, const desia::CheckOptions& options, bool json,
                 const std::string& unit, double contactTolerance) {
  std::vector<desia::MeshFile> inputs;
  for (const std::string& file : files) inputs.push_back({file, desia::cli::readInputFile(file)});
  desia::MeshAssemblyOptions meshOptions;
  meshOptions.contactTolerance = contactTolerance;
  const desia::MeshAssembly meshes =
      desia::buildMeshAssembly(desia::readMeshParts(inputs, desia::parseLengthUnit(unit)), meshOptions);
  const desia::CheckReport report = desia::checkMeshAssembly(meshes, options);
  std::cout << (json ? desia::meshCheckReportToJson(meshes, report) + "\n" : desia::meshCheckReportToText(meshes, report));
  return desia::checkPassed(report) ? 0 : 1;
}
