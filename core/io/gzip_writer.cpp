// SPDX-License-Identifier: GPL-3.0-or-later
// A minimal gzip writer for the BurrTools .xmpuzzle export.
//
// Why our own and not zlib: the same core runs natively and as WebAssembly, and both must produce
// the same bytes. zlib is there natively (zlib1g-dev) but would have to be built for WebAssembly
// as well (or taken from Emscripten's port, fetched at build time), and compressed output also
// depends on the zlib version and its settings. BurrTools reads any valid gzip stream, compressed
// or not, so storing the XML uncompressed in DEFLATE "stored" blocks (RFC 1951, section 3.2.4)
// gives a valid file from a few lines of code: identical everywhere, no dependency. The price is
// size: the file is the XML plus 5 bytes per 64 KiB; pieces are cropped to their bounding boxes
// (xmpuzzle_format.cpp) to keep the XML small.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/export.h"
#include "io/export_internals.h"

namespace desia {

std::vector<uint8_t> gzipStored(const std::string& data) {
  constexpr size_t kMaxStoredBlock = 65535;  // LEN is 16 bits
  std::vector<uint8_t> out;
  out.reserve(data.size() + data.size() / kMaxStoredBlock * 5 + 32);
  // Header (RFC 1952, 2.3): magic, CM = 8 (deflate), FLG = 0 (no name, no comment), MTIME = 0 (no
  // time stamp: the bytes depend on the content only), XFL = 0, OS = 255 (unknown).
  for (uint8_t byte : {0x1f, 0x8b, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff}) out.push_back(byte);
  // Stored blocks: a byte holding BFINAL and BTYPE = 00 (the rest of the byte is the padding to the
  // byte boundary), LEN and its one's complement NLEN, then LEN bytes as they are. At least one
  // block, so empty data still ends with a final block.
  size_t offset = 0;
  do {
    const size_t length = std::min(kMaxStoredBlock, data.size() - offset);
    const bool last = offset + length == data.size();
    out.push_back(last ? 0x01 : 0x00);
    appendLittleEndian(out, static_cast<uint32_t>(length), 2);
    appendLittleEndian(out, static_cast<uint32_t>(~length & 0xFFFFu), 2);
    out.insert(out.end(), data.begin() + static_cast<std::ptrdiff_t>(offset),
               data.begin() + static_cast<std::ptrdiff_t>(offset + length));
    offset += length;
  } while (offset < data.size());
  // Trailer: CRC-32 and ISIZE (the length modulo 2^32), both little-endian.
  appendLittleEndian(out, crc32(data), 4);
  appendLittleEndian(out, static_cast<uint32_t>(data.size() & 0xFFFFFFFFu), 4);
  return out;
}

}  // namespace desia
