// SPDX-License-Identifier: GPL-3.0-or-later
#include "design_run.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <limits>

#include "cli_arguments.h"
#include "cli_files.h"
#include "desia/document.h"
#include "desia/document_check.h"
#include "desia/error.h"

namespace desia::cli {
namespace {

// Set by Ctrl-C; every search polls it after each node (from its own thread with --jobs) and
// stops with what it has. A lock-free atomic: safe in a signal handler and across threads.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the Ctrl-C flag must be usable in a signal handler");
extern "C" void onInterrupt(int) { interrupted = true; }

// Seconds >= 0 (0 = no limit), at most 1e7.
double secondsOption(const std::string& flag, const std::string& text) {
  size_t used = 0;
  double value = -1;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value >= 0) || value > 1e7) {
    throw Error(ErrorCode::BadInput, flag + " expects a number of seconds >= 0, got '" + text + "'");
  }
  return value;
}

}  // namespace

bool parseSearchFlag(const std::string& flag, const std::string& value, const SearchFlags& into) {
  if (flag == "--seed") {
    *into.seed = static_cast<uint64_t>(integerOption(flag, value, 0, 1LL << 62));
  } else if (flag == "--candidates") {
    *into.candidates = static_cast<int>(integerOption(flag, value, 1, 10000));
  } else if (flag == "--time-limit") {
    into.limits->timeLimitSeconds = secondsOption(flag, value);
  } else if (flag == "--node-limit") {
    into.limits->nodeLimit = integerOption(flag, value, 1, 1LL << 50);
  } else {
    return false;
  }
  return true;
}

double CommandClock::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void CommandClock::leaveRestToSearch(DesignLimits* limits) const {
  if (limits->timeLimitSeconds <= 0) return;
  // Nothing left: the smallest positive limit, so that the search stops at its first look at the clock.
  limits->timeLimitSeconds = std::max(limits->timeLimitSeconds - seconds(), std::numeric_limits<double>::min());
}

LiveProgress::LiveProgress(bool quiet, std::string suffix) : live_(!quiet && isatty(STDERR_FILENO)), suffix_(std::move(suffix)) {
  interrupted = false;
  std::signal(SIGINT, onInterrupt);
}

LiveProgress::~LiveProgress() {
  std::signal(SIGINT, SIG_DFL);
  if (live_) std::fprintf(stderr, "\r%78s\r", "");
}

std::function<bool(const DesignProgress&)> LiveProgress::callback() {
  return [this](const DesignProgress& p) {
    if (live_ && (p.seconds - lastShown_ > 0.2 || lastShown_ < 0)) {
      lastShown_ = p.seconds;
      std::fprintf(stderr, "\r%lld nodes, depth %d/%d, best %d/%d, %.1f s%s   ", static_cast<long long>(p.nodes), p.depth,
                   p.targetParts, p.bestDepth, p.targetParts, p.seconds, suffix_.c_str());
    }
    return !interrupted;
  };
}

int writeVerifiedResult(const std::string& input, const std::string& output, const std::string& text,
                        const CheckOptions& check, const std::string& message, double seconds, const char* what) {
  const AssemblyDocument written = parseAssemblyText(text, output);
  const CheckReport report = checkDocument(written, check);
  if (!checkPassed(report) || !report.shapeRemoval) {
    std::cerr << "desia: " << input << ": the " << what << " found did not verify, nothing written to " << output << ":\n"
              << checkReportToText(written, report);
    return 1;
  }
  writeOutputFile(output, text);
  std::cout << message << " in " << seconds << " s\n"
            << "verified: " << checkReportToText(written, report) << "written: " << output << "\n";
  return 0;
}

}  // namespace desia::cli
