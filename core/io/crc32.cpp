// SPDX-License-Identifier: GPL-3.0-or-later
// The CRC-32 and little-endian integers shared by the gzip (.xmpuzzle) and ZIP (stl-zip) writers.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/export_internals.h"

namespace desia {
namespace {

// Reflected polynomial 0xEDB88320, one table entry per byte value, built at compile time.
constexpr std::array<uint32_t, 256> makeCrcTable() {
  std::array<uint32_t, 256> table{};
  for (uint32_t n = 0; n < 256; ++n) {
    uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}
constexpr std::array<uint32_t, 256> kCrcTable = makeCrcTable();

}  // namespace

uint32_t crc32(const std::string& data) {
  uint32_t crc = 0xFFFFFFFFu;
  for (const char byte : data) crc = kCrcTable[(crc ^ static_cast<uint8_t>(byte)) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

void appendLittleEndian(std::vector<uint8_t>& out, uint32_t value, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<uint8_t>((value >> (8 * k)) & 0xFFu));
}

}  // namespace desia
