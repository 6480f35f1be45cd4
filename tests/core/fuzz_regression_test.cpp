// SPDX-License-Identifier: GPL-3.0-or-later
// Replays the fuzzers' inputs through the very functions the libFuzzer harnesses call
// (tests/fuzz/fuzz_targets.h), natively and in WebAssembly: every crash ever found
// (tests/fuzz/regressions/<harness>/) and the seed corpus (tests/fuzz/corpus/<harness>/). An input
// may be refused with desia::Error; any other exception is a failure (crashes and sanitizer
// reports end the run, and the sanitizer build runs this test too).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz_targets.h"

namespace desia {
namespace fuzz {
// Test names and failure messages show the harness, not a byte dump of the struct.
void PrintTo(const Target& target, std::ostream* out) { *out << target.name; }
}  // namespace fuzz

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> filesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // a stable order, so a failure reproduces the same way
  return files;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs one input; returns an empty string when it passed, otherwise what escaped.
std::string replay(const fuzz::Target& target, const std::string& bytes) {
  try {
    target.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    return "";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

class FuzzReplay : public ::testing::TestWithParam<fuzz::Target> {};

TEST_P(FuzzReplay, RegressionsAreRefusedOrAcceptedWithoutOtherExceptions) {
  const fs::path folder = fs::path(DESIA_FUZZ_DIR) / "regressions" / GetParam().name;
  for (const fs::path& file : filesIn(folder)) {
    const std::string escaped = replay(GetParam(), readBytes(file));
    EXPECT_EQ(escaped, "") << file.string();
  }
}

TEST_P(FuzzReplay, SeedCorpusRunsWithoutOtherExceptions) {
  const fs::path folder = fs::path(DESIA_FUZZ_DIR) / "corpus" / GetParam().name;
  const std::vector<fs::path> files = filesIn(folder);
  // A wrong path must not pass vacuously: every harness has seeds.
  ASSERT_FALSE(files.empty()) << folder.string();
  for (const fs::path& file : files) {
    const std::string escaped = replay(GetParam(), readBytes(file));
    EXPECT_EQ(escaped, "") << file.string();
  }
}

INSTANTIATE_TEST_SUITE_P(Harnesses, FuzzReplay, ::testing::ValuesIn(fuzz::targets()),
                         [](const ::testing::TestParamInfo<fuzz::Target>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace desia
