// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/text_lines.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "desia/error.h"

namespace desia {

std::string location(const std::string& source, int line, int column) {
  std::string where = source + ":" + std::to_string(line);
  if (column > 0) where += ":" + std::to_string(column);
  return where;
}

bool TextLineReader::next(TextLine& line) {
  if (finished_) return false;
  line.number = ++lineNumber_;
  line.tokens.clear();
  int column = 1;
  while (offset_ < text_.size()) {
    const unsigned char c = static_cast<unsigned char>(text_[offset_]);
    if (c == '\n') {
      ++offset_;
      if (!line.tokens.empty()) lastLineWithData_ = line.number;
      return true;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++column;
      ++offset_;
      continue;
    }
    if (c < 0x20 || c == 0x7f || c >= 0x80) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throwBadInput(location(source_, line.number, column),
                    std::string("not a text file: unexpected byte ") + hex + " at offset " + std::to_string(offset_));
    }
    Token token{"", column};
    while (offset_ < text_.size()) {
      const unsigned char t = static_cast<unsigned char>(text_[offset_]);
      if (t == ' ' || t == '\t' || t == '\r' || t == '\n' || t < 0x20 || t >= 0x7f) break;
      token.text.push_back(static_cast<char>(t));
      ++offset_;
      ++column;
    }
    line.tokens.push_back(std::move(token));
  }
  // The text ended without a final newline: this is its last line.
  finished_ = true;
  if (!line.tokens.empty()) lastLineWithData_ = line.number;
  return true;
}

int64_t parseIntegerToken(const Token& token, const std::string& source, int line, const std::string& what,
                          int64_t minValue, int64_t maxValue) {
  const std::string where = location(source, line, token.column);
  const std::string& s = token.text;
  size_t digitsFrom = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  bool digits = s.size() > digitsFrom;
  for (size_t k = digitsFrom; k < s.size(); ++k) digits = digits && s[k] >= '0' && s[k] <= '9';
  if (!digits) throwBadInput(where, what + " '" + s + "' is not an integer");
  errno = 0;
  const long long value = std::strtoll(s.c_str(), nullptr, 10);
  if (errno == ERANGE || value > maxValue || value < minValue) {
    throwBadInput(where, what + " " + s + " is out of range (" + std::to_string(minValue) + " to " +
                             std::to_string(maxValue) + ")");
  }
  return value;
}

}  // namespace desia
