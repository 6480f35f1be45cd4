// SPDX-License-Identifier: GPL-3.0-or-later
// desia design frame: a thin shell over designFrame (core/include/desia/frame_design.h).
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <iostream>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "desia/check.h"
#include "desia/document_check.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/frame_design.h"
#include "desia/frame_format.h"

namespace {

volatile std::sig_atomic_t interrupted = 0;
extern "C" void onFrameDesignInterrupt(int) { interrupted = 1; }

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
    else if (flag == "--seed")
      options.seed = static_cast<uint64_t>(desia::cli::integerOption(flag, value, 0, 1LL << 62));
    else if (flag == "--candidates")
      options.candidates = static_cast<int>(desia::cli::integerOption(flag, value, 1, 10000));
    else if (flag == "--node-limit")
      options.limits.nodeLimit = desia::cli::integerOption(flag, value, 1, 1LL << 50);
    else if (flag == "--time-limit")
      options.limits.timeLimitSeconds = positiveNumber(flag, value, 0, 1e7);
    else if (flag == "--joint-size")
      jointSize = positiveNumber(flag, value, 1e-9, 1e9);
    else
      usage("unknown option " + flag + " for design frame");
  }
  if (input.empty()) usage("design frame needs --input FRAME.obj|.json|.fpuz");
  if (output.empty() || !desia::cli::hasExtension(output, ".json")) usage("design frame needs --output RESULT.json");
  const desia::FrameDocument frame = desia::parseFrameText(desia::cli::readInputFile(input), input, jointSize);
  const bool live = !quiet && isatty(STDERR_FILENO);
  options.limits.onProgress = [&](const desia::DesignProgress& p) {
    if (live && p.nodes % 16 == 0) {
      std::fprintf(stderr, "\r%lld nodes, depth %d/%d, %.1f s   ", static_cast<long long>(p.nodes), p.depth + 1,
                   p.targetParts, p.seconds);
    }
    return interrupted == 0;
  };
  std::signal(SIGINT, onFrameDesignInterrupt);
  const desia::FrameDesignResult result = desia::designFrame(frame.layout, options);
  std::signal(SIGINT, SIG_DFL);
  if (live) std::fprintf(stderr, "\r%70s\r", "");
  if (result.status != desia::DesignStatus::Success) {
    std::cerr << "desia: " << input << ": " << result.message << "\n";
    return 1;
  }
  const std::string name = frame.name.empty() ? "" : frame.name;
  const std::string text = desia::frameResultToJson(frame.layout, result, name) + "\n";
  // What the user gets is checked as it will be written, before anything is written: the DBG test
  // on its voxel contacts, and the swept removal of every beam in order.
  const desia::AssemblyDocument written = desia::parseAssemblyText(text, output);
  const desia::CheckReport report = desia::checkDocument(written);
  if (!desia::checkPassed(report) || !report.shapeRemoval) {
    std::cerr << "desia: " << input << ": the design found did not verify, nothing written to " << output << ":\n"
              << desia::checkReportToText(written, report);
    return 1;
  }
  desia::cli::writeOutputFile(output, text);
  std::cout << result.message << " in " << result.progress.seconds << " s\n"
            << "verified: " << desia::checkReportToText(written, report) << "written: " << output << "\n";
  return 0;
}
