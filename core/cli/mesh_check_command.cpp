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
  const desia::MeshCheck check = desia::checkMeshFiles(inputs, desia::parseLengthUnit(unit), meshOptions, options);
  std::cout << (json ? desia::meshCheckReportToJson(check.meshes, check.report) + "\n"
                     : desia::meshCheckReportToText(check.meshes, check.report));
  return desia::checkPassed(check.report) ? 0 : 1;
}
