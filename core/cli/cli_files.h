// SPDX-License-Identifier: GPL-3.0-or-later
// File reading and writing for the command line, with the size limit and the messages every
// sub-command shares.
#pragma once

#include <string>

namespace desia::cli {

// Reads a whole file; throws desia::Error (bad input / too large) naming the path.
std::string readInputFile(const std::string& path);
// Writes `text` to `path`; throws desia::Error naming the path when it cannot.
void writeOutputFile(const std::string& path, const std::string& text);
// Case-insensitive "does the path end with this extension" (".puz", ".json").
bool hasExtension(const std::string& path, const std::string& extension);

}  // namespace desia::cli
