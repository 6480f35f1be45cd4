// SPDX-License-Identifier: GPL-3.0-or-later
// desia design frame: a thin shell over designFrame (core/include/desia/frame.h).
#include <iostream>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "design_run.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/frame.h"

namespace {

[[noreturn]] void usage(const std::string& message) { throw desia::Error(desia::ErrorCode::BadInput, message); }

double positiveNumber(const std::string& flag, const std::string& text, double lo, double hi) {
  size_t used = 0;
  double value = -1;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value >= lo) || !(value <= hi)) {
    usage(flag + " expects a number from " + std::to_string(lo).substr(0, 3) + " to " +
          std::to_string(static_cast<long long>(hi)) + ", got '" + text + "'");
  }
  return value;
}

}  // namespace

int runFrameDesignCommand(const std::vector<std::string>& args) {
  desia::cli::CommandClock clock;
  std::string input, output;
  desia::FrameDesignOptions options;
  double jointSize = 0;
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
    else if (flag == "--joint-size")
      jointSize = positiveNumber(flag, value, 1e-9, 1e9);
    else
      usage("unknown option " + flag + " for design frame");
  }
  if (input.empty()) usage("design frame needs --input FRAME.obj|.json|.fpuz");
  if (output.empty() || !desia::cli::hasExtension(output, ".json")) usage("design frame needs --output RESULT.json");
  const desia::FrameDocument frame = desia::parseFrameText(desia::cli::readInputFile(input), input, jointSize);
  desia::FrameDesignResult result;
  {
    desia::cli::LiveProgress progress(quiet);
    options.limits.onProgress = progress.callback();
    clock.leaveRestToSearch(&options.limits);
    result = desia::designFrame(frame.layout, options);
  }
  if (result.status != desia::DesignStatus::Success) {
    std::cerr << "desia: " << input << ": " << result.message << "\n";
    return 1;
  }
  // What the user gets is checked as it will be written, before anything is written: the DBG test
  // on its voxel contacts, and the swept removal of every beam in order.
  const std::string text = desia::frameResultToJson(frame.layout, result, frame.name) + "\n";
  return desia::cli::writeVerifiedResult(input, output, text, {}, result.message, result.progress.seconds, "design", clock);
}
