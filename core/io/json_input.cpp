// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/json_input.h"

#include <vector>

#include "desia/error.h"

namespace desia {
namespace {

using nlohmann::json;

// Line and column of a byte offset.
std::string locationOfOffset(const std::string& text, const std::string& source, size_t offset) {
  int line = 1, column = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return source + ":" + std::to_string(line) + ":" + std::to_string(column);
}

// One open object or array while scanning: which member or element of it we are in.
struct OpenValue {
  bool isArray = false;
  size_t index = 0;
  std::string key;
};

std::string pathOf(const std::vector<OpenValue>& open) {
  constexpr size_t kShown = 8;
  std::string path;
  for (size_t i = 0; i + 1 < open.size() && i < kShown; ++i) {
    if (open[i].isArray) {
      path += "[" + std::to_string(open[i].index) + "]";
    } else {
      path += (path.empty() ? "" : ".") + open[i].key;
    }
  }
  if (open.size() > kShown + 1) path += "...";
  return path.empty() ? "the document" : path;
}

// A linear scan over the text (strings skipped, escapes honoured) that tracks the open objects
// and arrays, so that the nesting limit is enforced before the JSON library recurses.
void refuseDeepNesting(const std::string& text, const std::string& source) {
  std::vector<OpenValue> open;
  bool inString = false, escaped = false, expectingKey = false, readingKey = false;
  std::string key;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
        if (readingKey && !open.empty()) open.back().key = key;
        readingKey = false;
        continue;
      }
      if (readingKey && key.size() < 64) key += c;
      continue;
    }
    switch (c) {
      case '"':
        inString = true;
        readingKey = expectingKey;
        expectingKey = false;
        key.clear();
        break;
      case '{':
      case '[':
        if (static_cast<int>(open.size()) >= kMaxJsonNesting) {
          throwBadInput(locationOfOffset(text, source, i),
                        pathOf(open) + ": values nested more than " + std::to_string(kMaxJsonNesting) + " levels deep");
        }
        open.push_back({c == '[', 0, ""});
        expectingKey = c == '{';
        break;
      case '}':
      case ']':
        if (!open.empty()) open.pop_back();
        expectingKey = false;
        break;
      case ',':
        if (!open.empty()) {
          if (open.back().isArray) {
            ++open.back().index;
          } else {
            expectingKey = true;
          }
        }
        break;
      default:
        break;
    }
  }
}

}  // namespace

json parseJsonText(const std::string& text, const std::string& source, const json::parser_callback_t& callback) {
  refuseDeepNesting(text, source);
  try {
    return json::parse(text, callback);
  } catch (const json::parse_error& e) {
    std::string message = e.what();
    // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 1, column 2: ".
    const size_t colon = message.find(": ");
    if (colon != std::string::npos) message = message.substr(colon + 2);
    throwBadInput(locationOfOffset(text, source, e.byte > 0 ? e.byte - 1 : 0), "malformed JSON: " + message);
  } catch (const json::exception& e) {
    // Other reader failures, e.g. "number overflow parsing '1e999'" (out_of_range.406).
    std::string message = e.what();
    const size_t bracket = message.find("] ");
    if (bracket != std::string::npos) message = message.substr(bracket + 2);
    throwBadInput(source, "malformed JSON: " + message);
  }
}

}  // namespace desia
