// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli_files.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "desia/error.h"

namespace desia::cli {
namespace {
constexpr std::streamoff kMaxInputBytes = 512LL << 20;
}

std::string readInputFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw Error(ErrorCode::BadInput, path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::BadInput, path + ": cannot open the file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(ErrorCode::BadInput, path + ": cannot read the file (is it a directory?)");
  if (size > kMaxInputBytes) {
    throw Error(ErrorCode::TooLarge, path + ": the file is " + std::to_string(size) + " bytes, more than the limit of " +
                                         std::to_string(kMaxInputBytes) + " bytes");
  }
  in.seekg(0);
  std::string text(static_cast<size_t>(size), '\0');
  in.read(text.data(), size);
  if (!in) throw Error(ErrorCode::BadInput, path + ": cannot read the file");
  return text;
}

void writeOutputFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (out) out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw Error(ErrorCode::BadInput, path + ": cannot write the file");
}

bool hasExtension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  for (size_t k = 0; k < extension.size(); ++k) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(path[path.size() - extension.size() + k])));
    if (c != extension[k]) return false;
  }
  return true;
}

}  // namespace desia::cli
