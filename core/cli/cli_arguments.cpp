// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_arguments.h"

#include <algorithm>

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

}  // namespace desia::cli
