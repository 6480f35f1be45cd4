// SPDX-License-Identifier: GPL-3.0-or-later
// desia design plate: a thin shell over designPlateJoints (core/include/desia/plate.h).
#include <iostream>
#include <optional>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "design_run.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/plate.h"

namespace {

[[noreturn]] void usage(const std::string& message) { throw desia::Error(desia::ErrorCode::BadInput, message); }

// A cut point: named, with the repair the core proposes (paper Fig. 18) written to `repairOutput`
// when asked for, else offered. Exit 1 either way: the design as given cannot interlock.
int reportCutPoint(const desia::AssemblyDocument& document, const std::string& input, const std::string& message,
                   const std::string& repairOutput) {
  std::cerr << "desia: " << input << ": " << message << "\n";
  const std::optional<desia::PlateRepair> repair = desia::proposeCutPointRepair(document.plates, document.plateOptions);
  if (!repair) {
    std::cerr << "desia: no bar joining the groups was found: add a part by hand\n";
    return 1;
  }
  if (repairOutput.empty()) {
    std::cerr << "desia: a repair exists (" << repair->message << "): write it with --repair REPAIRED.json\n";
    return 1;
  }
  desia::AssemblyDocument repaired =
      desia::documentFromPlates(repair->plates, document.plateOptions, input, document.name + " (repaired)");
  desia::cli::writeOutputFile(repairOutput, desia::documentToJson(repaired) + "\n");
  std::cerr << "desia: " << repair->message << "; wrote " << repairOutput << " (design it with desia design plate)\n";
  return 1;
}

}  // namespace

int runPlateDesignCommand(const std::vector<std::string>& args) {
  desia::cli::CommandClock clock;
  std::string input, output, repairOutput;
  desia::PlateDesignOptions options;
  options.realization = desia::JointRealization::Auto;  // cut if possible, else milled, else planned
  bool quiet = false;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--quiet") {
      quiet = true;
      continue;
    }
    if (i + 1 == args.size()) usage(flag + " needs a value");
    const std::string& value = args[++i];
    if (flag == "--input")
      input = value;
    else if (flag == "--output")
      output = value;
    else if (desia::cli::parseSearchFlag(flag, value, {&options.seed, &options.candidates, &options.limits}))
      continue;
    else if (flag == "--repair")
      repairOutput = value;
    else if (flag == "--joints")
      options.realization = desia::parseJointRealization(value);
    else if (flag == "--clearance")
      options.joints.clearance = desia::cli::numberOption(flag, value, 0, 10);
    else if (flag == "--tenon-width")
      options.joints.tenonWidth = desia::cli::numberOption(flag, value, 1, 10000);
    else if (flag == "--tenon-count")
      options.joints.tenonCount = static_cast<int>(desia::cli::integerOption(flag, value, 1, 20));
    else if (flag == "--joint-size") {
      // NAME=VALUE, e.g. dovetail.slope=0.2 (desia::jointSizeSettings lists them).
      const size_t equals = value.find('=');
      if (equals == std::string::npos) usage("--joint-size expects NAME=VALUE (e.g. dovetail.slope=0.2), got '" + value + "'");
      const std::string name = value.substr(0, equals);
      desia::setJointSize(options.joints, name,
                          desia::cli::numberOption("--joint-size " + name, value.substr(equals + 1), -1e300, 1e300));
    }
    else
      usage("unknown option " + flag + " for design plate");
  }
  if (input.empty()) usage("design plate needs --input DESIGN.json|.obj|.stl");
  if (output.empty() || !desia::cli::hasExtension(output, ".json")) usage("design plate needs --output RESULT.json");
  if (!repairOutput.empty() && !desia::cli::hasExtension(repairOutput, ".json")) usage("--repair needs a .json file");
  // A design from a modelling tool (one OBJ object per plate, or an STL of separate slabs), or JSON.
  const bool mesh = desia::cli::hasExtension(input, ".obj") || desia::cli::hasExtension(input, ".stl");
  const std::string bytes = desia::cli::readInputFile(input);
  const desia::AssemblyDocument document =
      mesh ? desia::documentFromPlates(desia::platesFromMesh(desia::parseMesh(bytes, input), {}, input), {}, input)
           : desia::parseAssemblyText(bytes, input);
  if (document.kind != desia::AssemblyKind::Plate || document.plates.empty()) {
    usage(input + ": design plate needs a plate design (kind \"plate\" with \"plates\" and no \"contacts\")");
  }
  options.geometry = document.plateOptions;
  desia::PlateDesignResult result;
  {
    desia::cli::LiveProgress progress(quiet);
    options.limits.onProgress = progress.callback();
    clock.leaveRestToSearch(&options.limits);
    result = desia::designPlateJoints(document.plates, document.plateContacts, options);
  }
  if (result.status == desia::DesignStatus::CutPoint)
    return reportCutPoint(document, input, result.message, repairOutput);
  if (result.status != desia::DesignStatus::Success) {
    std::cerr << "desia: " << input << ": " << result.message << "\n";
    return 1;
  }
  // What the user gets is checked as it will be written, by the check `desia check` runs (both
  // tests and, on the plates, the removal replayed), before anything is written.
  desia::CheckOptions check;
  check.method = desia::CheckMethod::Both;
  return desia::cli::writeVerifiedResult(input, output, desia::plateDesignToJson(document, result) + "\n", check,
                                         result.message, result.progress.seconds, "plan", clock);
}
