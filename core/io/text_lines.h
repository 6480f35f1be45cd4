// SPDX-License-Identifier: GPL-3.0-or-later
// Line-oriented tokenizing with locations, shared by the text readers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace desia {

struct Token {
  std::string text;
  int column = 0;  // 1-based
};

struct TextLine {
  int number = 0;  // 1-based
  std::vector<Token> tokens;
};

// Splits text into lines of whitespace-separated tokens (accepting \n and \r\n). Throws BadInput
// for binary content (a NUL or other control byte), naming its offset.
std::vector<TextLine> splitTextLines(const std::string& text, const std::string& source);

// "source:line:column" (column omitted when 0).
std::string location(const std::string& source, int line, int column = 0);

// Parses a decimal integer token in [minValue, maxValue]; throws BadInput with the location and
// `what` (e.g. "voxel value") otherwise.
int64_t parseIntegerToken(const Token& token, const std::string& source, int line, const std::string& what,
                          int64_t minValue, int64_t maxValue);

}  // namespace desia
