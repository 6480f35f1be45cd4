// SPDX-License-Identifier: GPL-3.0-or-later
// desia design voxel: a thin shell over designVoxelPuzzle (core/include/desia/voxel.h).
#include <iostream>

#include "cli_arguments.h"
#include "cli_files.h"
#include "commands.h"
#include "design_portfolio.h"
#include "design_run.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/voxel.h"

namespace {

struct DesignArguments {
  std::string input, output, groupsFile;
  desia::VoxelDesignOptions options;
  int jobs = desia::cli::defaultDesignJobs();
  bool quiet = false;
};

[[noreturn]] void usage(const std::string& message) { throw desia::Error(desia::ErrorCode::BadInput, message); }

DesignArguments parseArguments(const std::vector<std::string>& args) {
  if (args.empty() || args[0] != "voxel") usage("design expects a kind: 'desia design voxel ...', 'desia design plate ...' or 'desia design frame ...'");
  DesignArguments parsed;
  bool partsGiven = false;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--quiet") {
      parsed.quiet = true;
      continue;
    }
    if (flag == "--even-parts") {
      parsed.options.evenParts = true;
      continue;
    }
    if (i + 1 == args.size()) usage(flag + " needs a value");
    const std::string& value = args[++i];
    if (flag == "--input") parsed.input = value;
    else if (flag == "--output") parsed.output = value;
    else if (flag == "--groups") parsed.groupsFile = value;
    else if (flag == "--parts") { parsed.options.parts = static_cast<int>(desia::cli::integerOption(flag, value, 1, 1000000)); partsGiven = true; }
    else if (desia::cli::parseSearchFlag(flag, value, {&parsed.options.seed, &parsed.options.candidates, &parsed.options.limits})) continue;
    else if (flag == "--rank") parsed.options.ranking = desia::parseCandidateRanking(value);
    else if (flag == "--mode") parsed.options.mode = desia::parseDesignMode(value);
    else if (flag == "--min-part-size") parsed.options.minPartSize = static_cast<int>(desia::cli::integerOption(flag, value, 1, 1000000));
    else if (flag == "--max-part-size") parsed.options.maxPartSize = static_cast<int>(desia::cli::integerOption(flag, value, 1, 1000000));
    else if (flag == "--jobs") parsed.jobs = static_cast<int>(desia::cli::integerOption(flag, value, 1, 256));
    else if (flag == "--key-direction") parsed.options.keyDirection = desia::parseAxisDirection(value, "--key-direction");
    else usage("unknown option " + flag);
  }
  if (parsed.input.empty()) usage("design voxel needs --input SHAPE.puz|SHAPE.json");
  if (parsed.output.empty()) usage("design voxel needs --output OUT.puz|OUT.json");
  if (!partsGiven) usage("design voxel needs --parts N");
  if (!desia::cli::hasExtension(parsed.output, ".puz") && !desia::cli::hasExtension(parsed.output, ".json")) {
    usage("--output " + parsed.output + ": the file name must end in .puz or .json");
  }
  return parsed;
}

// "seeds 1-4 on 4 threads"
std::string seedsText(const DesignArguments& parsed) {
  const uint64_t first = parsed.options.seed, last = first + static_cast<uint64_t>(parsed.jobs) - 1;
  return "seeds " + std::to_string(first) + "-" + std::to_string(last) + " on " + std::to_string(parsed.jobs) + " threads";
}

}  // namespace

int runDesignCommand(const std::vector<std::string>& args) {
  if (!args.empty() && args[0] == "plate") return runPlateDesignCommand(args);
  if (!args.empty() && args[0] == "frame") return runFrameDesignCommand(args);
  desia::cli::CommandClock clock;
  DesignArguments parsed = parseArguments(args);
  const desia::AssemblyDocument document = desia::parseAssemblyText(desia::cli::readInputFile(parsed.input), parsed.input);
  if (document.kind != desia::AssemblyKind::Voxel) {
    throw desia::Error(desia::ErrorCode::BadInput, parsed.input + ": design voxel needs a voxel shape, not a " +
                                                       desia::assemblyKindName(document.kind) + " document");
  }
  if (!parsed.groupsFile.empty()) parsed.options.groups = desia::parseVoxelGroupsJson(desia::cli::readInputFile(parsed.groupsFile), document.voxels, parsed.groupsFile);
  desia::VoxelDesignResult result;
  {
    desia::cli::LiveProgress progress(parsed.quiet, parsed.jobs > 1 ? ", " + std::to_string(parsed.jobs) + " seeds" : "");
    parsed.options.limits.onProgress = progress.callback();
    clock.leaveRestToSearch(&parsed.options.limits);
    result = desia::cli::designVoxelPortfolio(document.voxels, parsed.options, parsed.jobs);
  }
  if (result.status != desia::DesignStatus::Success) {
    std::cerr << "desia: " << result.message << (parsed.jobs > 1 ? " (" + seedsText(parsed) + ", the deepest shown)" : "") << "\n";
    return 1;
  }
  const std::string text = desia::cli::hasExtension(parsed.output, ".json")
                               ? desia::documentToJson(desia::documentFromVoxels(result.puzzle)) + "\n"
                               : desia::formatPuz(result.puzzle);
  desia::cli::writeOutputFile(parsed.output, text);
  std::cout << result.message << " in " << result.progress.seconds << " s\n"
            << "seed: " << result.seed;
  if (parsed.jobs > 1) std::cout << " won (" << seedsText(parsed) << "; --jobs 1 --seed " << result.seed << " gives this puzzle)";
  std::cout << "\npart sizes: min " << result.partSizes.min << ", max " << result.partSizes.max << ", mean "
            << result.partSizes.mean << "\n"
            << "verified: " << desia::checkReportToText(desia::documentFromVoxels(result.puzzle), result.verification)
            << "written: " << parsed.output << "\n";
  return 0;
}
