// SPDX-License-Identifier: GPL-3.0-or-later
// 3MF files (issue 29): a ZIP (zip_reader.cpp) of XML parts (three_mf.cpp) whose model holds the objects and a build
// of items with their transforms. Internal to io; mesh_input.h is the public reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/mesh.h"

namespace desia {

// The entries of a ZIP archive that the readers need, by name, ZIP64 or not. Stored and deflated
// entries (inflated by zlib); sizes, offsets and CRC-32s are checked against the archive, and an
// entry larger than kMaxEntryBytes is TooLarge. Errors name `source` and the entry.
class ZipArchive {
 public:
  static constexpr size_t kMaxEntryBytes = 512u * 1024 * 1024;  // the CLI's file-size cap

  ZipArchive(const std::string& bytes, std::string source);
  bool has(const std::string& name) const;
  // The entry's bytes (BadInput when it is missing or damaged).
  std::string read(const std::string& name) const;

 private:
  struct Entry {
    std::string name;
    int method = 0;
    uint32_t crc = 0;
    size_t compressedSize = 0;
    size_t size = 0;
    size_t localHeader = 0;
  };
  void readZip64Extra(size_t extra, size_t length, Entry* entry) const;
  const std::string& bytes_;
  std::string source_;
  std::vector<Entry> entries_;
};

// Every build item of a 3MF file as a part: its object's meshes (and those of its components,
// each with its own transform) under the item's transform, in millimetres from the model's
// `unit`. Part names: the object's `name`, else "object ID". Errors (BadInput) name the file, the
// model part, the line and the element.
std::vector<MeshPart> readThreeMfParts(const std::string& bytes, const std::string& source);

}  // namespace desia
