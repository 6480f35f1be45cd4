// SPDX-License-Identifier: GPL-3.0-or-later
#include "design_run.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <iostream>
#include <limits>

#include "cli_arguments.h"
#include "cli_files.h"
#include "desia/document.h"
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

// The search's share of what is left of the command's time limit; the rest is kept for checking
// the result as written (that check costs a fraction of the search that found it: the 1,002-plate
// table with cut joints, 5 s of checking after 32 s of designing).
constexpr double kSearchShareOfRest = 0.85;

double CommandClock::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void CommandClock::leaveRestToSearch(DesignLimits* limits) {
  if (limits->timeLimitSeconds <= 0) return;
  commandLimitSeconds_ = limits->timeLimitSeconds;
  // Nothing left: the smallest positive limit, so that the search stops at its first look at the clock.
  limits->timeLimitSeconds =
      std::max(kSearchShareOfRest * (limits->timeLimitSeconds - seconds()), std::numeric_limits<double>::min());
}

double CommandClock::secondsLeft() const {
  if (commandLimitSeconds_ <= 0) return HUGE_VAL;
  return commandLimitSeconds_ - seconds();
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

namespace {

struct VerifiedText {
  AssemblyDocument written;
  CheckReport report;
};

// Ends the process with exit 1 and `message` if it is not called off before `seconds` pass. It
// only waits: the check runs on the calling thread (whose allocator arena holds the memory the
// search let go of; a check on a thread of its own took a second arena, 32 MB more for 1,002
// plates), and a check cannot be stopped halfway, so the process ends (std::_Exit does not wait).
class Watchdog {
 public:
  Watchdog(double seconds, std::string message)
      : message_(std::move(message)), thread_([this, seconds] { watch(seconds); }) {}
  ~Watchdog() {
    callOff();
    thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
  // After this returns the process is not ended by the watchdog (the file may then be written).
  void callOff() {
    std::lock_guard<std::mutex> lock(mutex_);
    calledOff_ = true;
    wake_.notify_one();
  }

 private:
  void watch(double seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(std::max(seconds, 0.0));
    if (wake_.wait_until(lock, deadline, [this] { return calledOff_; })) return;
    std::cerr << message_;
    std::cout.flush();
    std::cerr.flush();
    std::_Exit(1);
  }

  std::string message_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool calledOff_ = false;
  std::thread thread_;  // last: started once the members it uses exist
};

// The text read back and checked; when the command's time limit runs out first the process ends
// there with exit 1 and nothing written.
VerifiedText verifyWithinLimit(const std::string& input, const std::string& output, const std::string& text,
                               const CheckOptions& check, const char* what, const CommandClock& clock) {
  std::optional<Watchdog> watchdog;
  const double left = clock.secondsLeft();
  if (std::isfinite(left)) {
    std::ostringstream message;
    message << "desia: " << input << ": the time limit ran out while the " << what
            << " found was being checked as written; nothing written to " << output << " (give a longer --time-limit)\n";
    watchdog.emplace(left, message.str());
  }
  AssemblyDocument written = parseAssemblyText(text, output);
  CheckReport report = checkDocument(written, check);
  if (watchdog) watchdog->callOff();
  return VerifiedText{std::move(written), std::move(report)};
}

}  // namespace

int writeVerifiedResult(const std::string& input, const std::string& output, const std::string& text,
                        const CheckOptions& check, const std::string& message, double seconds, const char* what,
                        const CommandClock& clock) {
  const VerifiedText verified = verifyWithinLimit(input, output, text, check, what, clock);
  const AssemblyDocument& written = verified.written;
  const CheckReport& report = verified.report;
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
