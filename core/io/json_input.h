// SPDX-License-Identifier: GPL-3.0-or-later
// Reading JSON text for every desia reader: syntax errors with line and column, and documents
// nested too deeply refused before they are parsed.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace desia {

// No desia document needs more than a handful of levels; the JSON library copies and writes
// nested values recursively, so a document nested 100,000 levels deep would overflow the stack.
constexpr int kMaxJsonNesting = 256;

// Parses `text`; throws BadInput naming `source`, line and column for malformed JSON, and the
// path of the first value nested deeper than kMaxJsonNesting.
nlohmann::json parseJsonText(const std::string& text, const std::string& source,
                             const nlohmann::json::parser_callback_t& callback = nullptr);

}  // namespace desia
