// SPDX-License-Identifier: GPL-3.0-or-later
// A minimal ZIP writer for the stl-zip export (one STL per part), written from PKWARE's APPNOTE.TXT
// (version 6.3.x, sections 4.3.7 local file header, 4.3.12 central directory header, 4.3.16 end of
// central directory record).
//
// Stored entries (method 0), for the reason the gzip writer stores its blocks: the same bytes
// natively and in WebAssembly without zlib. Binary STL compresses poorly anyway (float
// coordinates). Every entry carries the first DOS date (1980-01-01 00:00): no clock, no time zone,
// so the archive depends on its content only.
#include <cstdint>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "io/export_internals.h"

namespace desia {
namespace {

constexpr uint32_t kLocalHeaderSignature = 0x04034b50u;
constexpr uint32_t kCentralHeaderSignature = 0x02014b50u;
constexpr uint32_t kEndOfCentralDirectorySignature = 0x06054b50u;
constexpr uint16_t kVersionNeeded = 10;  // 1.0: stored entries, no directories, no ZIP64
constexpr uint16_t kVersionMadeBy = 20;  // 2.0 of the specification, host 0 (MS-DOS attributes)
constexpr uint16_t kDosTime = 0;         // 00:00:00
constexpr uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980 + 0, month 1, day 1
constexpr uint64_t kMaxEntries = 0xFFFF;
constexpr uint64_t kMaxOffset = 0xFFFFFFFFull;

// The fields a local header and its central directory header share, from "version needed" on.
void appendCommonFields(std::vector<uint8_t>& out, const ZipEntry& entry, uint32_t crc) {
  appendLittleEndian(out, kVersionNeeded, 2);
  appendLittleEndian(out, 0, 2);  // flags: none (names are ASCII, sizes known up front)
  appendLittleEndian(out, 0, 2);  // compression method: stored
  appendLittleEndian(out, kDosTime, 2);
  appendLittleEndian(out, kDosDate, 2);
  appendLittleEndian(out, crc, 4);
  appendLittleEndian(out, static_cast<uint32_t>(entry.data.size()), 4);  // compressed size
  appendLittleEndian(out, static_cast<uint32_t>(entry.data.size()), 4);  // uncompressed size
  appendLittleEndian(out, static_cast<uint32_t>(entry.name.size()), 2);
  appendLittleEndian(out, 0, 2);  // extra field length
}

void appendText(std::vector<uint8_t>& out, const std::string& text) { out.insert(out.end(), text.begin(), text.end()); }

}  // namespace

std::vector<uint8_t> zipStored(const std::vector<ZipEntry>& entries) {
  uint64_t total = 22;
  for (const ZipEntry& entry : entries) total += 30 + 46 + 2 * entry.name.size() + entry.data.size();
  if (entries.size() > kMaxEntries || total > kMaxOffset) {
    throw Error(ErrorCode::TooLarge, "a ZIP archive of " + std::to_string(entries.size()) + " files and " +
                                         std::to_string(total >> 20) +
                                         " MiB is beyond a plain ZIP (65,535 files, 4 GiB; ZIP64 is not written)");
  }
  std::vector<uint8_t> out;
  out.reserve(static_cast<size_t>(total));
  std::vector<uint32_t> crcs, offsets;
  for (const ZipEntry& entry : entries) {
    crcs.push_back(crc32(entry.data));
    offsets.push_back(static_cast<uint32_t>(out.size()));
    appendLittleEndian(out, kLocalHeaderSignature, 4);
    appendCommonFields(out, entry, crcs.back());
    appendText(out, entry.name);
    appendText(out, entry.data);
  }
  const uint32_t centralDirectoryOffset = static_cast<uint32_t>(out.size());
  for (size_t k = 0; k < entries.size(); ++k) {
    appendLittleEndian(out, kCentralHeaderSignature, 4);
    appendLittleEndian(out, kVersionMadeBy, 2);
    appendCommonFields(out, entries[k], crcs[k]);
    appendLittleEndian(out, 0, 2);  // file comment length
    appendLittleEndian(out, 0, 2);  // disk number start
    appendLittleEndian(out, 0, 2);  // internal attributes (0: binary)
    appendLittleEndian(out, 0, 4);  // external attributes (0: a plain file)
    appendLittleEndian(out, offsets[k], 4);
    appendText(out, entries[k].name);
  }
  const uint32_t centralDirectorySize = static_cast<uint32_t>(out.size()) - centralDirectoryOffset;
  appendLittleEndian(out, kEndOfCentralDirectorySignature, 4);
  appendLittleEndian(out, 0, 2);  // number of this disk
  appendLittleEndian(out, 0, 2);  // disk where the central directory starts
  appendLittleEndian(out, static_cast<uint32_t>(entries.size()), 2);  // entries on this disk
  appendLittleEndian(out, static_cast<uint32_t>(entries.size()), 2);  // entries in all
  appendLittleEndian(out, centralDirectorySize, 4);
  appendLittleEndian(out, centralDirectoryOffset, 4);
  appendLittleEndian(out, 0, 2);  // comment length
  return out;
}

}  // namespace desia
