// SPDX-License-Identifier: GPL-3.0-or-later
// Errors raised by the core. Each boundary (CLI, embind) turns them into its own form:
// exit code 2 on the command line, a JS Error in WebAssembly.
#pragma once

#include <stdexcept>
#include <string>

namespace desia {

enum class ErrorCode {
  BadInput,      // malformed file or document, impossible parameter
  TooLarge,      // input refused before allocating (grid or part count above the limits)
  Unsupported,   // valid input the requested method cannot handle
  Internal,      // a bug or a solver failure; never expected
  KindNotBuilt,  // a plate or frame asked of a build without them (the light WebAssembly module):
                 // the package loads the full module and asks again (docs/architecture.md)
};

class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const { return code_; }

 private:
  ErrorCode code_;
};

// Raised for malformed input; `where` is a location such as "file.puz:12:3" (may be empty).
[[noreturn]] void throwBadInput(const std::string& where, const std::string& what);

const char* errorCodeName(ErrorCode code);

}  // namespace desia
