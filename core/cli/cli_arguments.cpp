// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_arguments.h"

#include <cmath>
#include <sstream>

#include <algorithm>

#include "desia/error.h"

namespace desia::cli {

Arguments splitArguments(const std::vector<std::string>& args, const std::vector<std::string>& valueOptions) {
  Arguments result;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("-", 0) != 0 || arg == "-") {
      result.positional.push_back(arg);
      continue;
    }
    NamedValue option{arg, ""};
    bool hasValue = false;
    const size_t equals = arg.find('=');
    if (arg.rfind("--", 0) == 0 && equals != std::string::npos) {
      option.name = arg.substr(0, equals);
      option.value = arg.substr(equals + 1);
      hasValue = true;
    }
    if (std::find(valueOptions.begin(), valueOptions.end(), option.name) == valueOptions.end()) {
      throw UsageError{"unknown option " + arg};
    }
    if (!hasValue) {
      if (i + 1 == args.size()) throw UsageError{option.name + " needs a value"};
      option.value = args[++i];
    }
    result.named.push_back(std::move(option));
  }
  return result;
}

int parseDigits(const std::string& text, const std::string& message) {
  bool digits = !text.empty() && text.size() <= 9;
  for (char c : text) digits = digits && c >= '0' && c <= '9';
  if (!digits) throw UsageError{message};
  return std::stoi(text);
}

long long integerOption(const std::string& flag, const std::string& text, long long lo, long long hi) {
  size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty()) throw Error(ErrorCode::BadInput, flag + " expects an integer, got '" + text + "'");
  if (value < lo || value > hi) {
    throw Error(ErrorCode::BadInput, flag + " " + text + " is out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  }
  return value;
}

double numberOption(const std::string& flag, const std::string& text, double lo, double hi) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw Error(ErrorCode::BadInput, flag + " expects a number, got '" + text + "'");
  }
  if (value < lo || value > hi) {
    std::ostringstream range;
    range << lo << " to " << hi;
    throw Error(ErrorCode::BadInput, flag + " " + text + " is out of range (" + range.str() + ")");
  }
  return value;
}

}  // namespace desia::cli
