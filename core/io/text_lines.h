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

// Reads text one line of whitespace-separated tokens at a time (accepting \n and \r\n), so a
// large file never exists as a list of tokens. Throws BadInput for binary content (a NUL or
// other control byte), naming its offset.
class TextLineReader {
 public:
  TextLineReader(const std::string& text, const std::string& source) : text_(text), source_(source) {}
  // Fills `line` with the next line (possibly without tokens); false at the end of the text.
  bool next(TextLine& line);
  // Number of the last line that had tokens (1 when none had).
  int lastLineWithData() const { return lastLineWithData_; }

 private:
  const std::string& text_;
  const std::string& source_;
  size_t offset_ = 0;
  int lineNumber_ = 0;
  int lastLineWithData_ = 1;
  bool finished_ = false;
};

// "source:line:column" (column omitted when 0).
std::string location(const std::string& source, int line, int column = 0);

// Parses a decimal integer token in [minValue, maxValue]; throws BadInput with the location and
// `what` (e.g. "voxel value") otherwise.
int64_t parseIntegerToken(const Token& token, const std::string& source, int line, const std::string& what,
                          int64_t minValue, int64_t maxValue);

}  // namespace desia
