// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the entries of a ZIP archive (the container of 3MF files): the central directory, then
// each entry stored or deflated, inflated by zlib (APPNOTE.TXT 4.3: end of central directory,
// central directory headers, local headers; 4.3.14-4.3.15 and 4.5.3: the ZIP64 records and extra
// field, which lib3mf writes for every 3MF). Encrypted entries are refused.
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "desia/error.h"
#include "three_mf.h"

namespace desia {
namespace {

constexpr uint32_t kEndOfDirectorySignature = 0x06054b50;
constexpr uint32_t kDirectoryHeaderSignature = 0x02014b50;
constexpr uint32_t kLocalHeaderSignature = 0x04034b50;
constexpr size_t kEndOfDirectorySize = 22;
constexpr size_t kMaxCommentSize = 65535;
constexpr size_t kDirectoryHeaderSize = 46;
constexpr size_t kLocalHeaderSize = 30;
// Deflate expands at most about 1032-fold (a 258-byte match per bit pair, RFC 1951): an entry that
// claims more than this of its compressed size is damaged, and refused before it is allocated.
constexpr size_t kMaxDeflateRatio = 1032;
constexpr size_t kDeflateSlackBytes = 1024;
constexpr int kStored = 0;
constexpr int kDeflated = 8;
constexpr uint16_t kEncryptedFlag = 1;
constexpr uint32_t kZip64Marker = 0xffffffffu;
constexpr uint32_t kZip64CountMarker = 0xffffu;
constexpr uint32_t kZip64LocatorSignature = 0x07064b50;
constexpr uint32_t kZip64EndSignature = 0x06064b50;
constexpr size_t kZip64LocatorSize = 20;
constexpr size_t kZip64EndSize = 56;
constexpr uint32_t kZip64ExtraId = 0x0001;

// Little-endian fields at `at`, inside `bytes` (the callers check the bounds first).
uint32_t field16(const std::string& bytes, size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
  return static_cast<uint32_t>(p[0] | (p[1] << 8));
}

uint32_t field32(const std::string& bytes, size_t at) {
  return field16(bytes, at) | (field16(bytes, at + 2) << 16);
}

uint64_t field64(const std::string& bytes, size_t at) {
  return field32(bytes, at) | (static_cast<uint64_t>(field32(bytes, at + 4)) << 32);
}

// A 64-bit size or offset as size_t, refused when it cannot lie inside `limit` bytes.
size_t boundedBy(uint64_t value, size_t limit, const std::string& where, const char* what) {
  if (value > limit) throwBadInput(where, std::string("the ZIP's ") + what + " lies outside the file");
  return static_cast<size_t>(value);
}

// Raw deflate data (no zlib header, window bits -15) to exactly `size` bytes.
std::string inflated(const std::string& bytes, size_t start, size_t compressedSize, size_t size, const std::string& where) {
  std::string out(size, '\0');
  z_stream stream{};
  if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) throw Error(ErrorCode::Internal, where + ": zlib could not start inflating");
  // zlib's counters are 32-bit (uInt): entries are capped below that by kMaxEntryBytes.
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + start));
  stream.avail_in = static_cast<uInt>(compressedSize);
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(size);
  const int status = inflate(&stream, Z_FINISH);
  const size_t produced = stream.total_out;
  inflateEnd(&stream);
  if (status != Z_STREAM_END || produced != size) {
    throwBadInput(where, "the compressed data is damaged (inflate stopped after " + std::to_string(produced) + " of " +
                             std::to_string(size) + " bytes)");
  }
  return out;
}

}  // namespace

ZipArchive::ZipArchive(const std::string& bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {
  if (bytes.size() < kEndOfDirectorySize) throwBadInput(source_, "not a ZIP archive (too short); a 3MF file is one");
  // The end record is last, before a comment of at most 64 KiB: search backwards for it.
  const size_t lowest = bytes.size() > kEndOfDirectorySize + kMaxCommentSize ? bytes.size() - kEndOfDirectorySize - kMaxCommentSize : 0;
  size_t end = bytes.size() - kEndOfDirectorySize;
  while (field32(bytes, end) != kEndOfDirectorySignature) {
    if (end == lowest) throwBadInput(source_, "not a ZIP archive (no end of central directory); a 3MF file is one");
    --end;
  }
  uint64_t count = field16(bytes, end + 10);
  uint64_t directorySize = field32(bytes, end + 12);
  uint64_t directoryStart = field32(bytes, end + 16);
  size_t directoryEnd = end;
  if (count == kZip64CountMarker || directorySize == kZip64Marker || directoryStart == kZip64Marker) {
    // ZIP64: the locator just before the end record points at the ZIP64 end record.
    if (end < kZip64LocatorSize || field32(bytes, end - kZip64LocatorSize) != kZip64LocatorSignature) {
      throwBadInput(source_, "the ZIP64 end of central directory locator is missing");
    }
    const size_t record = boundedBy(field64(bytes, end - kZip64LocatorSize + 8), end - kZip64LocatorSize, source_, "ZIP64 end record");
    if (end - kZip64LocatorSize - record < kZip64EndSize || field32(bytes, record) != kZip64EndSignature) {
      throwBadInput(source_, "the ZIP64 end of central directory record is damaged");
    }
    count = field64(bytes, record + 32);
    directorySize = field64(bytes, record + 40);
    directoryStart = field64(bytes, record + 48);
    directoryEnd = record;
  }
  if (directoryStart > directoryEnd || directorySize > directoryEnd - directoryStart) {
    throwBadInput(source_, "the ZIP's central directory lies outside the file");
  }
  end = directoryEnd;
  size_t at = directoryStart;
  for (uint64_t k = 0; k < count; ++k) {
    if (at + kDirectoryHeaderSize > end || field32(bytes, at) != kDirectoryHeaderSignature) {
      throwBadInput(source_, "the ZIP's central directory is damaged at entry " + std::to_string(k + 1));
    }
    Entry entry;
    const uint32_t flags = field16(bytes, at + 8);
    entry.method = static_cast<int>(field16(bytes, at + 10));
    entry.crc = field32(bytes, at + 16);
    entry.compressedSize = field32(bytes, at + 20);
    entry.size = field32(bytes, at + 24);
    const size_t nameLength = field16(bytes, at + 28);
    const size_t skipped = nameLength + field16(bytes, at + 30) + field16(bytes, at + 32);
    entry.localHeader = field32(bytes, at + 42);
    if (at + kDirectoryHeaderSize + skipped > end) throwBadInput(source_, "the ZIP's central directory is damaged at entry " + std::to_string(k + 1));
    entry.name = bytes.substr(at + kDirectoryHeaderSize, nameLength);
    readZip64Extra(at + kDirectoryHeaderSize + nameLength, field16(bytes, at + 30), &entry);
    if (flags & kEncryptedFlag) throw Error(ErrorCode::Unsupported, source_ + ": " + entry.name + ": encrypted ZIP entries are not read");
    entries_.push_back(std::move(entry));
    at += kDirectoryHeaderSize + skipped;
  }
}

// The ZIP64 extra field (id 1) of a central directory header: the 64-bit values of the fields
// whose 32-bit value is 0xffffffff, in the order size, compressed size, local header offset.
void ZipArchive::readZip64Extra(size_t extra, size_t length, Entry* entry) const {
  const std::string where = source_ + ": " + entry->name;
  for (size_t at = extra; at + 4 <= extra + length;) {
    const uint32_t id = field16(bytes_, at);
    const size_t size = field16(bytes_, at + 2);
    if (at + 4 + size > extra + length) throwBadInput(where, "the ZIP entry's extra field is damaged");
    if (id == kZip64ExtraId) {
      size_t next = at + 4;
      for (size_t* value : {&entry->size, &entry->compressedSize, &entry->localHeader}) {
        if (*value != kZip64Marker) continue;
        if (next + 8 > at + 4 + size) throwBadInput(where, "the ZIP64 extra field is too short");
        // Clamped to 32 bits (size_t in WebAssembly): anything that large is beyond the file and
        // kMaxEntryBytes, which read() refuses.
        *value = static_cast<size_t>(std::min<uint64_t>(field64(bytes_, next), UINT32_MAX));
        next += 8;
      }
    }
    at += 4 + size;
  }
}

bool ZipArchive::has(const std::string& name) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& entry) { return entry.name == name; });
}

std::string ZipArchive::read(const std::string& name) const {
  const auto found = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& entry) { return entry.name == name; });
  if (found == entries_.end()) throwBadInput(source_, "the ZIP has no entry '" + name + "'");
  const Entry& entry = *found;
  const std::string where = source_ + ": " + name;
  if (entry.size > kMaxEntryBytes) {
    throw Error(ErrorCode::TooLarge, where + ": " + std::to_string(entry.size) + " bytes unpacked, more than the limit of " +
                                         std::to_string(kMaxEntryBytes));
  }
  const size_t header = entry.localHeader;
  if (header > bytes_.size() || bytes_.size() - header < kLocalHeaderSize || field32(bytes_, header) != kLocalHeaderSignature) {
    throwBadInput(where, "the entry's local header is missing or damaged");
  }
  const size_t start = header + kLocalHeaderSize + field16(bytes_, header + 26) + field16(bytes_, header + 28);
  if (start > bytes_.size() || entry.compressedSize > bytes_.size() - start) throwBadInput(where, "the entry's data run past the end of the file");
  std::string data;
  if (entry.method == kStored) {
    if (entry.compressedSize != entry.size) throwBadInput(where, "a stored entry whose two sizes differ");
    data = bytes_.substr(start, entry.size);
  } else if (entry.method == kDeflated) {
    if (entry.size / kMaxDeflateRatio > entry.compressedSize + kDeflateSlackBytes) {
      throwBadInput(where, "the entry claims " + std::to_string(entry.size) + " bytes from " + std::to_string(entry.compressedSize) +
                               " compressed, more than deflate can produce");
    }
    data = inflated(bytes_, start, entry.compressedSize, entry.size, where);
  } else {
    throw Error(ErrorCode::Unsupported, where + ": ZIP compression method " + std::to_string(entry.method) +
                                            " is not read (only stored and deflated)");
  }
  const uLong crc = ::crc32(::crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size()));
  if (crc != entry.crc) throwBadInput(where, "the entry's CRC-32 does not match its data (the file is damaged)");
  return data;
}

}  // namespace desia
