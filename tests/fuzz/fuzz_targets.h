// SPDX-License-Identifier: GPL-3.0-or-later
// The bodies of the fuzz harnesses, shared by the libFuzzer binaries (tests/fuzz/*_fuzz.cpp) and the
// GoogleTest replay of the regression corpus (tests/core/fuzz_regression_test.cpp), so a crash file
// is replayed through exactly the code that found it.
//
// Contract of every target: desia::Error is a normal outcome (the input was refused with a message);
// anything else — a crash, a sanitizer report, any other exception, a broken invariant (reported as
// std::logic_error) or a timeout — is a finding.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/mesh.h"
#include "desia/plate.h"
#include "desia/voxel.h"

namespace desia::fuzz {

struct Target {
  const char* name;  // also the folder name under tests/fuzz/corpus/ and tests/fuzz/regressions/
  void (*run)(const uint8_t* data, size_t size);
};

namespace detail {

inline std::string textOf(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Runs `body`, swallowing the refusals the readers are allowed to give.
template <typename Body>
void refusalsAllowed(Body&& body) {
  try {
    body();
  } catch (const desia::Error&) {
  }
}

[[noreturn]] inline void broken(const std::string& what) { throw std::logic_error("fuzz invariant broken: " + what); }

}  // namespace detail

// .puz and JSON assembly documents through the reader the CLI and the module use. A document that
// was read must serialize and read back (the JSON writer must never produce what the reader refuses).
inline void assemblyTextTarget(const uint8_t* data, size_t size) {
  detail::refusalsAllowed([&] {
    const AssemblyDocument document = parseAssemblyText(detail::textOf(data, size), "fuzz");
    const std::string json = documentToJson(document, -1);
    try {
      const AssemblyDocument again = parseAssemblyText(json, "fuzz-roundtrip");
      if (again.assembly.partCount() != document.assembly.partCount())
        detail::broken("part count changed in a round trip");
    } catch (const desia::Error& e) {
      detail::broken(std::string("a written document was refused: ") + e.what());
    }
  });
}

// OBJ / STL: each reader on its own, the dispatcher under both extensions, then the closed-mesh
// check and a coarse voxelization of whatever the readers accepted.
inline void meshTarget(const uint8_t* data, size_t size) {
  const std::string bytes = detail::textOf(data, size);
  const auto voxelizeCoarse = [](const TriangleMesh& mesh) {
    checkClosedMesh(mesh, "fuzz");
    VoxelizeOptions options;
    options.resolution = 8;  // enough to walk every code path; a fuzz run must stay fast
    voxelizeSolid(mesh, options, "fuzz");
  };
  detail::refusalsAllowed([&] { voxelizeCoarse(parseObj(bytes, "fuzz.obj")); });
  detail::refusalsAllowed([&] { voxelizeCoarse(parseStl(bytes, "fuzz.stl")); });
  detail::refusalsAllowed([&] { parseMesh(bytes, "fuzz.obj"); });
  detail::refusalsAllowed([&] { parseMesh(bytes, "fuzz.stl"); });
  // Plate designs from modelling tools: each object (or slab) a plate, then the whole structure.
  detail::refusalsAllowed([&] {
    const TriangleMesh mesh = parseObj(bytes, "fuzz.obj");
    if (mesh.triangles.size() > 2000) return;
    documentFromPlates(platesFromMesh(mesh, {}, "fuzz.obj"), {}, "fuzz.obj");
  });
}

// The design options and appearance-group readers (package options, --groups files) against a fixed
// 4x4x4 shape with a hole, so "outside the shape" paths are reachable.
inline void designOptionsTarget(const uint8_t* data, size_t size) {
  VoxelGrid shape(4, 4, 4);
  for (int64_t i = 0; i < shape.voxelCount(); ++i) shape.setLabelAt(i, 1);
  shape.setLabel(1, 1, 1, 0);
  const std::string text = detail::textOf(data, size);
  detail::refusalsAllowed([&] { parseDesignOptionsJson(text, shape); });
  detail::refusalsAllowed([&] { parseVoxelGroupsJson(text, shape, "fuzz.json"); });
  detail::refusalsAllowed([&] { parseAxisDirection(text); });
}

// Limits that keep one checkAssembly run in the milliseconds (GLPK's LPs grow with the parts).
struct CheckLimits {
  static constexpr size_t kMaxBytes = 8192;
  static constexpr int kMaxParts = 16;
  static constexpr int64_t kMaxVoxels = 512;
  static constexpr size_t kMaxContacts = 128;
};

// checkAssembly with every method on small documents, and both report writers.
inline void checkTarget(const uint8_t* data, size_t size) {
  if (size > CheckLimits::kMaxBytes) return;
  detail::refusalsAllowed([&] {
    const AssemblyDocument document = parseAssemblyText(detail::textOf(data, size), "fuzz");
    if (document.assembly.partCount() > CheckLimits::kMaxParts ||
        document.voxels.voxelCount() > CheckLimits::kMaxVoxels ||
        document.assembly.contacts.size() > CheckLimits::kMaxContacts) {
      return;
    }
    for (const CheckMethod method : {CheckMethod::Graphs, CheckMethod::Inequalities, CheckMethod::Both}) {
      CheckOptions options;
      options.method = method;
      // As `desia check`: the tests on the contacts and, for plate and frame results, the removal
      // plan replayed on the shapes.
      const CheckReport report = checkDocument(document, options);
      checkReportToJson(document, report, -1);
      checkReportToText(document, report);
    }
  });
}

// Limits for the designer: tiny shapes, few parts, a node budget instead of a clock (reproducible).
struct DesignLimits {
  static constexpr size_t kHeaderBytes = 4;
  static constexpr int64_t kMaxShapeVoxels = 64;
  static constexpr int64_t kMaxGridVoxels = 512;
  static constexpr int64_t kNodeLimit = 40;
};

// designVoxelPuzzle on a tiny shape. Input: a 4-byte header choosing the options, then a .puz or
// JSON voxel document whose non-empty voxels are the shape (the CLI's rule).
//   byte 0: parts = 3 + b % 4            byte 1: seed
//   byte 2: candidates = 1 + b % 8, bit 3 recursive mode, bits 4-5 minPartSize, bit 6 a group of
//           the first two shape voxels
//   byte 3: ranking = b % 7, key direction = (b / 7) % 6
// A success must re-check as interlocking with key 1 (the designer's promise).
inline void designTarget(const uint8_t* data, size_t size) {
  if (size < DesignLimits::kHeaderBytes) return;
  const uint8_t* header = data;
  detail::refusalsAllowed([&] {
    const AssemblyDocument document =
        parseAssemblyText(detail::textOf(data + DesignLimits::kHeaderBytes, size - DesignLimits::kHeaderBytes), "fuzz");
    if (document.kind != AssemblyKind::Voxel || document.voxels.voxelCount() > DesignLimits::kMaxGridVoxels) return;
    std::vector<int64_t> shapeVoxels;
    for (int64_t i = 0; i < document.voxels.voxelCount(); ++i) {
      if (document.voxels.labelAt(i) != 0) shapeVoxels.push_back(i);
    }
    if (static_cast<int64_t>(shapeVoxels.size()) > DesignLimits::kMaxShapeVoxels) return;

    static const char* const kRankings[] = {"compactness", "x", "y", "z", "-x", "-y", "-z"};
    static const char* const kDirections[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    VoxelDesignOptions options;
    options.parts = 3 + header[0] % 4;
    options.seed = header[1];
    options.candidates = 1 + header[2] % 8;
    options.mode = (header[2] & 0x08) ? DesignMode::Recursive : DesignMode::Desia;
    options.minPartSize = (header[2] >> 4) & 0x03;
    if ((header[2] & 0x40) && shapeVoxels.size() >= 2) options.groups = {{shapeVoxels[0], shapeVoxels[1]}};
    options.ranking = parseCandidateRanking(kRankings[header[3] % 7]);
    options.keyDirection = parseAxisDirection(kDirections[(header[3] / 7) % 6]);
    options.limits.nodeLimit = DesignLimits::kNodeLimit;

    const VoxelDesignResult result = designVoxelPuzzle(document.voxels, options);
    designResultToJson(result);
    if (result.status != DesignStatus::Success) return;
    const AssemblyDocument designed = documentFromVoxels(result.puzzle);
    if (designed.assembly.partCount() != options.parts) detail::broken("a design has the wrong part count");
    const CheckReport check = checkAssembly(designed);
    if (check.result.verdict != Verdict::Interlocking || check.result.key != 0) {
      detail::broken("a designed puzzle does not interlock with part 1 as its key");
    }
  });
}

// Frames as the CLI reads them: FrameInterlock .fpuz, OBJ lines and faces, and the JSON frame
// document (the reader is chosen by the extension). A frame that was read must write a JSON
// document that reads back with as many beams.
inline void frameTextTarget(const uint8_t* data, size_t size) {
  if (size > 8192) return;  // frames of a few dozen beams walk every path; layout checks are quadratic
  const std::string text = detail::textOf(data, size);
  for (const char* source : {"fuzz.fpuz", "fuzz.obj", "fuzz.json"}) {
    detail::refusalsAllowed([&] {
      const FrameDocument frame = parseFrameText(text, source);
      try {
        const FrameDocument again = parseFrameText(frameDocumentToJson(frame, -1), "fuzz-roundtrip.json");
        if (again.layout.frame.beams.size() != frame.layout.frame.beams.size()) detail::broken("beam count changed in a round trip");
      } catch (const desia::Error& e) {
        detail::broken(std::string("a written frame was refused: ") + e.what());
      }
    });
  }
}

// The plate readers that are not assembly documents: plates from a low-poly mesh (plates-from-mesh),
// the designer's and the cut sheets' options; and the cut sheets of a small plate document.
inline void plateInputTarget(const uint8_t* data, size_t size) {
  const std::string text = detail::textOf(data, size);
  detail::refusalsAllowed([&] {
    const TriangleMesh mesh = parseObj(text, "fuzz.obj");
    if (mesh.triangles.size() > 500) return;
    MitredPlateOptions options;
    options.thickness = 2;
    const MitredPlates plates = mitredPlatesFromMesh(mesh, options, "fuzz.obj");
    documentFromPlates(plates.plates, {}, "fuzz.obj");
  });
  detail::refusalsAllowed([&] { parsePlateDesignOptionsJson(text); });
  detail::refusalsAllowed([&] { parseCutSheetOptionsJson(text); });
  detail::refusalsAllowed([&] {
    if (size > 8192) return;
    const AssemblyDocument document = parseAssemblyText(text, "fuzz.json");
    if (document.kind != AssemblyKind::Plate || document.plates.size() > 16) return;
    CutSheetOptions options;
    options.source = "fuzz";
    plateCutSheets(document, CutFileFormat::Svg, options);
  });
}

// Plate results as `desia check RESULT.json` reads them (issue 24: results that never lie). A
// result that passes must pass whatever the order of its arrays (parts, plates, contacts are
// matched by id), and must not pass with its key's way out reversed unless the key is free that
// way too. Results of up to 16 plates.
inline void plateResultTarget(const uint8_t* data, size_t size) {
  if (size > 131072) return;
  const std::string text = detail::textOf(data, size);
  CheckOptions options;
  options.method = CheckMethod::Both;
  detail::refusalsAllowed([&] {
    const AssemblyDocument document = parseAssemblyText(text, "fuzz.json");
    if (!document.plateResult || document.plates.size() > 16) return;
    const CheckReport report = checkDocument(document, options);
    checkReportToText(document, report);
    if (!checkPassed(report)) return;
    const nlohmann::json root = nlohmann::json::parse(text);  // the reader accepted it: JSON
    nlohmann::json reordered = root;
    for (const char* key : {"parts", "plates", "contacts", "fabricationPlates", "joints"}) {
      if (reordered.contains(key) && reordered[key].is_array()) {
        std::reverse(reordered[key].begin(), reordered[key].end());
      }
    }
    try {
      if (!checkPassed(checkDocument(parseAssemblyText(reordered.dump(), "fuzz-reordered"), options)))
        detail::broken("a passing plate result fails with its arrays reversed");
    } catch (const desia::Error& e) {
      detail::broken(std::string("a passing plate result is refused with its arrays reversed: ") + e.what());
    }
    nlohmann::json tampered = root;
    nlohmann::json& direction = tampered["removal"][0]["direction"];
    if (!direction.is_array() || direction.size() != 3) return;
    Vec3 reversed{};
    for (size_t k = 0; k < 3; ++k) {
      if (!direction[k].is_number()) return;
      reversed[k] = -direction[k].get<double>();
      direction[k] = reversed[k];
    }
    const AssemblyDocument turned = parseAssemblyText(tampered.dump(), "fuzz-reversed");
    if (!checkPassed(checkDocument(turned, options))) return;
    const double length = std::sqrt(reversed[0] * reversed[0] + reversed[1] * reversed[1] + reversed[2] * reversed[2]);
    for (const Vec3& free : report.result.keyDirections) {
      const double along = (free[0] * reversed[0] + free[1] * reversed[1] + free[2] * reversed[2]) / length;
      if (along > 1 - 1e-9) return;  // the key is free that way too
    }
    detail::broken("a plate result passes with its key's way out reversed");
  });
}

// Limits that keep one mesh assembly check in the milliseconds (the sweep and the plan grow with
// parts times triangles).
struct MeshAssemblyLimits {
  static constexpr size_t kMaxBytes = 65536;
  static constexpr size_t kMaxParts = 12;
  static constexpr size_t kMaxTriangles = 2000;
};

// The files of one mesh-assembly input: sections that start with a line "=== NAME" (NAME's
// extension chooses the reader, as the CLI's path does), and the line break before such a line is
// not the file's (so a binary STL keeps its exact size); text before the first such line, or an
// input without one, is a file of its own, "fuzz.obj".
inline std::vector<MeshFile> meshFilesOf(const std::string& bytes) {
  static const std::string kMarker = "=== ";
  std::vector<MeshFile> files{{"fuzz.obj", ""}};
  size_t lineStart = 0;
  while (lineStart < bytes.size()) {
    const size_t newline = bytes.find('\n', lineStart);
    const size_t lineEnd = newline == std::string::npos ? bytes.size() : newline + 1;
    if (bytes.compare(lineStart, kMarker.size(), kMarker) == 0) {
      std::string name = bytes.substr(lineStart + kMarker.size(), lineEnd - lineStart - kMarker.size());
      while (!name.empty() && (name.back() == '\n' || name.back() == '\r')) name.pop_back();
      std::string& previous = files.back().bytes;
      if (!previous.empty() && previous.back() == '\n') previous.pop_back();  // the marker's own line break
      files.push_back({name, ""});
    } else {
      files.back().bytes.append(bytes, lineStart, lineEnd - lineStart);
    }
    lineStart = lineEnd;
  }
  if (files.size() > 1 && files.front().bytes.empty()) files.erase(files.begin());
  return files;
}

// Mesh assemblies as `desia check A.obj B.stl ...` reads them (issue 29): several OBJ objects or
// groups, several STL files or solids, in one of three units (the input's first byte); then the
// validation, the contacts, both tests, the plan and both report writers. The parts read keep the
// ids 1..n, and the assembly has every part that was read.
inline void meshAssemblyTarget(const uint8_t* data, size_t size) {
  if (size == 0 || size > MeshAssemblyLimits::kMaxBytes) return;
  static const LengthUnit kUnits[] = {LengthUnit::Millimetre, LengthUnit::Metre, LengthUnit::Inch};
  const LengthUnit unit = kUnits[data[0] % 3];
  detail::refusalsAllowed([&] {
    std::vector<MeshPart> parts = readMeshParts(meshFilesOf(detail::textOf(data, size)), unit);
    size_t triangles = 0;
    for (size_t k = 0; k < parts.size(); ++k) {
      if (parts[k].id != static_cast<int>(k + 1)) detail::broken("mesh part ids are not 1..n in reading order");
      triangles += parts[k].mesh.triangles.size();
    }
    if (parts.size() > MeshAssemblyLimits::kMaxParts || triangles > MeshAssemblyLimits::kMaxTriangles) return;
    const size_t count = parts.size();
    const MeshAssembly meshes = buildMeshAssembly(std::move(parts));
    if (static_cast<size_t>(meshes.assembly.partCount()) != count) detail::broken("a mesh assembly lost parts");
    CheckOptions options;
    options.method = CheckMethod::Both;
    const CheckReport report = checkMeshAssembly(meshes, options);
    meshCheckReportToJson(meshes, report, -1);
    meshCheckReportToText(meshes, report);
  });
}

inline const std::vector<Target>& targets() {
  static const std::vector<Target> kTargets = {
      {"assembly_text", assemblyTextTarget},
      {"mesh", meshTarget},
      {"design_options", designOptionsTarget},
      {"check", checkTarget},
      {"design", designTarget},
      {"frame_text", frameTextTarget},
      {"plate_input", plateInputTarget},
      {"plate_result", plateResultTarget},
      {"mesh_assembly", meshAssemblyTarget},
  };
  return kTargets;
}

}  // namespace desia::fuzz
