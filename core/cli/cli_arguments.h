// SPDX-License-Identifier: GPL-3.0-or-later
// Command-line argument splitting shared by the sub-commands that take "--name value" options.
#pragma once

#include <string>
#include <vector>

namespace desia::cli {

// A usage mistake: the sub-command prints it with its usage line and exits with status 2.
struct UsageError {
  std::string message;
};

struct NamedValue {
  std::string name;  // "--format"
  std::string value;
};

struct Arguments {
  std::vector<std::string> positional;  // in order; "-" counts as one
  std::vector<NamedValue> named;        // in order, "--name value" and "--name=value" alike
};

// Splits `args`; every option must be one of `valueOptions` and takes a value. Throws UsageError
// naming an unknown option or an option without its value.
Arguments splitArguments(const std::vector<std::string>& args, const std::vector<std::string>& valueOptions);

// Digits only, at most 9 of them (so the value fits an int); throws UsageError(`message`) else.
int parseDigits(const std::string& text, const std::string& message);

// An integer option value within [lo, hi]; throws BadInput naming the flag and the value else.
long long integerOption(const std::string& flag, const std::string& text, long long lo, long long hi);

// A finite decimal option value within [lo, hi] (millimetres and the like); BadInput else.
double numberOption(const std::string& flag, const std::string& text, double lo, double hi);

}  // namespace desia::cli
