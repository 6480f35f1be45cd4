// SPDX-License-Identifier: GPL-3.0-or-later
// What the three `desia design` commands share: the search flags (--seed, --candidates,
// --time-limit, --node-limit, --quiet), the live progress line with Ctrl-C, and writing a result
// only after the project's check passed on it as written.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include "desia/document.h"
#include "desia/search.h"

namespace desia::cli {

// The flags every designer takes, parsed into the options' fields.
struct SearchFlags {
  uint64_t* seed;
  int* candidates;
  DesignLimits* limits;
};

// Consumes `flag value` when it is a search flag (true); false leaves it to the command.
bool parseSearchFlag(const std::string& flag, const std::string& value, const SearchFlags& into);

// --time-limit bounds the whole command, not the search alone: reading and checking the input
// count (a design of 9,998 plates takes seconds to read), the search gets most of what is left,
// and the check of the result as it will be written must end within the limit too.
class CommandClock {
 public:
  CommandClock() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const;
  // Remembers the command's limit, and makes the search's limit kSearchShareOfRest of what is
  // left of it (at least a moment: the search then stops after its first node, with what it has).
  // No limit stays no limit.
  void leaveRestToSearch(DesignLimits* limits);
  // Seconds left of the command's limit (infinite without one).
  double secondsLeft() const;

 private:
  std::chrono::steady_clock::time_point start_;
  double commandLimitSeconds_ = 0;  // 0: none
};

// While it lives: Ctrl-C stops the search (it keeps what it has), and a terminal sees one line of
// progress, redrawn at most five times a second (none with --quiet or when stderr is a file).
class LiveProgress {
 public:
  // `suffix` ends the line (e.g. ", 4 seeds").
  explicit LiveProgress(bool quiet, std::string suffix = "");
  ~LiveProgress();
  LiveProgress(const LiveProgress&) = delete;
  LiveProgress& operator=(const LiveProgress&) = delete;
  // The designer's onProgress: shows the line; false once Ctrl-C was pressed. Safe to call from
  // several threads one at a time (the voxel portfolio).
  std::function<bool(const DesignProgress&)> callback();

 private:
  bool live_;
  std::string suffix_;
  double lastShown_ = -1;
};

// Writes `text` (a result of `input`) to `output` after checkDocument passed on it as read back
// from that text, printing the designer's message, the time and the check; else says why and
// writes nothing. Returns the exit status (0 written, 1 not). When the command's time limit runs
// out before that check ends, the command ends there: a message, nothing written, exit 1.
// `what` names the result in that message ("plan", "design").
int writeVerifiedResult(const std::string& input, const std::string& output, const std::string& text,
                        const CheckOptions& check, const std::string& message, double seconds, const char* what,
                        const CommandClock& clock);

}  // namespace desia::cli
