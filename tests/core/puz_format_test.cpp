// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "test_support.h"

namespace desia {
namespace {

using testing::readFileText;
using testing::referencePath;

TEST(PuzFormat, WritesEveryReferenceFileBackByteForByte) {
  for (const char* file : {"result_puz/Cube_4x4x4_K9.puz", "result_puz/Cube_4x4x4_K9_01.puz", "result_puz/Cube_Hollow_4x4x4_K7",
                           "result_puz/cube_5x5x5_K16.puz", "result_puz/cartoon_dog.puz", "result_puz/bunny_15x14x11_K80.puz",
                           "input_puz/bunny_origin.puz", "input_puz/dog_origin.puz", "input_puz/Cube_hollow_4x4x4_origin.puz"}) {
    const std::string text = readFileText(referencePath(file));
    EXPECT_EQ(formatPuz(parsePuz(text, file)), text) << file;
  }
}

TEST(PuzFormat, XVariesFastestThenYThenZ) {
  // Header 3 2 2: rows have 3 values (x), 2 rows per layer (y), 2 layers (z).
  const VoxelGrid grid = parsePuz("3 2 2\n1 1 2 \n1 3 2 \n\n1 1 2 \n1 3 2 \n\n");
  EXPECT_EQ(grid.nx(), 3);
  EXPECT_EQ(grid.ny(), 2);
  EXPECT_EQ(grid.nz(), 2);
  EXPECT_EQ(grid.label(2, 0, 0), 2);
  EXPECT_EQ(grid.label(1, 1, 0), 3);
  EXPECT_EQ(grid.label(1, 1, 1), 3);
  EXPECT_EQ(grid.labels()[1 + 3 * (1 + 2 * 1)], 3);  // index x + nx*(y + ny*z)
}

TEST(PuzFormat, ReferenceSizesMatchTheirHeaders) {
  const VoxelGrid bunny = parsePuz(readFileText(referencePath("input_puz/bunny_origin.puz")));
  EXPECT_EQ(bunny.nx(), 15);
  EXPECT_EQ(bunny.ny(), 14);
  EXPECT_EQ(bunny.nz(), 11);
  EXPECT_EQ(bunny.labelCounts()[1], 966);
  const VoxelGrid dog = parsePuz(readFileText(referencePath("result_puz/cartoon_dog.puz")));
  EXPECT_EQ(dog.labelCounts(), (std::vector<int64_t>{19 * 14 * 7 - 581, 58, 17, 59, 59, 59, 59, 59, 59, 9, 18, 58, 14, 12, 41}));
}

TEST(PuzFormat, AcceptsWindowsLineEndingsAndExtraBlankLines) {
  const VoxelGrid grid = parsePuz("2 1 1\r\n\r\n1 1\r\n\r\n\r\n");
  EXPECT_EQ(grid.label(1, 0, 0), 1);
}

// The layout later interlocking-puzzle research writes: a '#' comment, a line of voxel sizes after
// the header, and the labels either as rows or as one flat list (x fastest, then y, then z).
TEST(PuzFormat, ReadsCommentsVoxelSizesAndFlatLists) {
  const std::string rows = "3 2 2\n1 1 2\n1 3 2\n\n1 1 2\n1 3 2\n";
  const VoxelGrid plain = parsePuz(rows);
  const PuzFile withSizes = readPuz("# puzzle 7, made by hand\n3 2 2\n0.250000 0.250000 0.250000\n# layer 1\n"
                                    "1 1 2\n1 3 2\n\n1 1 2\n1 3 2\n");
  EXPECT_EQ(withSizes.grid.labels(), plain.labels());
  ASSERT_TRUE(withSizes.voxelSize.has_value());
  EXPECT_EQ(*withSizes.voxelSize, (std::array<double, 3>{0.25, 0.25, 0.25}));
  EXPECT_FALSE(readPuz(rows).voxelSize.has_value());
  EXPECT_EQ(parsePuz("3 2 2\n0.5 0.5 1e0\n1 1 2 1 3 2 1 1 2 1 3 2\n").labels(), plain.labels());
  EXPECT_EQ(parsePuz("3 2 2\n1 1 2 1 3 2 1\n1 2\n1 3 2\n").labels(), plain.labels());
  // Three integers after the header are a row of labels, not voxel sizes.
  EXPECT_EQ(parsePuz("3 1 1\n1 1 2\n").label(2, 0, 0), 2);
  // The document keeps the sizes: exports take them as their voxel size.
  const AssemblyDocument document = parseAssemblyText("# sized\n3 1 1\n2.5 2.5 2.5\n1 1 2\n", "sized.puz");
  ASSERT_TRUE(document.voxelSize.has_value());
  EXPECT_EQ((*document.voxelSize)[0], 2.5);
}

struct BadPuz {
  const char* name;
  std::string text;
  std::string expected;  // substring of the message (with location)
  ErrorCode code = ErrorCode::BadInput;
};

// Readable test names in gtest output instead of a byte dump.
void PrintTo(const BadPuz& value, std::ostream* out) { *out << value.name; }

std::string withNul() { return std::string("2 1 1\n1 \0 1\n", 12); }

class BadPuzInput : public ::testing::TestWithParam<BadPuz> {};

TEST_P(BadPuzInput, IsRejectedWithLocationAndReason) {
  try {
    parsePuz(GetParam().text, "bad.puz");
    FAIL() << "accepted: " << GetParam().name;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), GetParam().code);
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Desia, BadPuzInput,
    ::testing::Values(
        BadPuz{"empty", "", "bad.puz: the file is empty"},
        BadPuz{"wrongHeader", "4 4\n", "bad.puz:1: the header must be three integers 'Nx Ny Nz', found 2 values"},
        BadPuz{"headerWord", "4 four 4\n", "bad.puz:1:3: grid size Ny 'four' is not an integer"},
        BadPuz{"zeroSize", "0 1 1\n", "bad.puz:1:1: grid size Nx 0 is out of range (1 to 1024)"},
        BadPuz{"raggedRow", "3 2 1\n1 1 1\n1 1\n", "bad.puz:3: row 2 of layer 1 has 2 values, expected Nx = 3"},
        BadPuz{"missingRows", "2 2 2\n1 1\n1 1\n\n1 1\n", "bad.puz:5: the file ends early: expected row 2 of 2 in layer 2 of 2"},
        BadPuz{"nonInteger", "2 1 1\n1 x\n", "bad.puz:2:3: voxel value 'x' is not an integer"},
        BadPuz{"floatValue", "2 1 1\n1 1.5\n", "bad.puz:2:3: voxel value '1.5' is not an integer"},
        BadPuz{"negativeLabel", "2 1 1\n1 -3\n", "bad.puz:2:3: voxel value -3 is out of range (0 to 2)"},
        BadPuz{"overflowingLabel", "2 1 1\n1 99999999999999999999\n", "bad.puz:2:3: voxel value 99999999999999999999 is out of range"},
        BadPuz{"dataAfterGrid", "2 1 1\n1 1\n\n7\n", "bad.puz:4:1: unexpected data after the last layer"},
        BadPuz{"allEmpty", "2 1 1\n0 0\n", "bad.puz: the assembly is empty: every voxel is 0"},
        BadPuz{"gapInIds", "3 1 1\n1 3 3\n", "bad.puz: part 2 has no voxels, but part 3 exists"},
        BadPuz{"disconnectedPart", "3 1 1\n1 2 1\n", "bad.puz: part 1 is not face-connected: it has 2 separate pieces (one contains voxel (0,0,0), another voxel (2,0,0))"},
        BadPuz{"diagonalOnly", "2 2 1\n1 2\n2 1\n", "part 1 is not face-connected"},
        BadPuz{"absurdSize", "100000 100000 100000\n", "bad.puz:1:1: grid size Nx 100000 is out of range (1 to 1024)"},
        BadPuz{"tooManyVoxels", "1024 1024 1024\n", "bad.puz:1: grid 1024 x 1024 x 1024 has more than 16777216 voxels", ErrorCode::TooLarge},
        BadPuz{"binaryGarbage", "\x89PNG\r\n\x1a\n", "bad.puz:1:1: not a text file: unexpected byte 0x89 at offset 0"},
        BadPuz{"nulByte", withNul(), "bad.puz:2:3: not a text file: unexpected byte 0x00 at offset 8"},
        BadPuz{"badVoxelSize", "# c\n2 1 1\n0.25 -1 0.25\n1 1\n", "bad.puz:3:6: the voxel size along y must be a positive number, found '-1'"},
        BadPuz{"onlyVoxelSizes", "2 1 1\n0.25 0.25 0.25\n", "bad.puz:2: the file ends after the voxel sizes: expected the voxel labels"},
        BadPuz{"flatTooLong", "2 1 2\n1 1 1 1 1\n", "bad.puz:2:9: more voxel values than the grid holds (2 x 1 x 2 = 4)"},
        BadPuz{"flatTooShort", "2 2 2\n1 1 1\n1 1\n", "bad.puz:3: the file ends early: 5 voxel values of 8 (grid 2 x 2 x 2)"},
        BadPuz{"onlyComments", "# nothing here\n# at all\n", "bad.puz: the file is empty"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace desia
