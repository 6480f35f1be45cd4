// SPDX-License-Identifier: GPL-3.0-or-later
// The full build's table of plate and frame entry points (io/kind_entries.h): the CLI, the tests
// and the full WebAssembly module link this file; the light module links io/light_entries.cpp.
// Also the kind-specific pieces the dispatch files reach through it: the plate and frame design
// sessions (desia/design_io.h), plates' surfaces and mesh exports.
#include <nlohmann/json.hpp>

#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"
#include "io/export_internals.h"
#include "io/frame/frame_check.h"
#include "io/frame/frame_json.h"
#include "io/kind_entries.h"
#include "io/plate/plate_check.h"
#include "io/plate/plate_document.h"
#include "io/plate/plate_format.h"

namespace desia {
namespace {

using nlohmann::json;

class PlateSession : public DesignSession {
 public:
  PlateSession(AssemblyDocument design, const std::string& optionsJson)
      : design_(std::move(design)),
        session_(design_.plates, design_.plateContacts, parsePlateDesignOptionsJson(optionsJson)) {}

  std::string stateJson() const override { return plateSessionStateToJson(design_, session_); }
  int childCount() override { return session_.childCount(); }
  std::string previewJson(int child) override { return plateStepToJson(design_, session_.childPreview(child)); }
  void choose(int child) override { session_.chooseChild(child); }
  bool next() override { return session_.next(); }
  bool back() override { return session_.back(); }
  std::string finishJson(const DesignLimits& limits) override {
    return plateDesignResultToJson(design_, session_.finish(limits));
  }
  // The verified result once complete (both tests, as a whole design), else the design as given.
  std::string checkJson() const override {
    CheckOptions options;
    if (!session_.complete()) return checkReportToJson(design_, checkDocument(design_, options), -1);
    const AssemblyDocument plan = parseJsonDocument(plateDesignToJson(design_, session_.result(), -1), "plan");
    options.method = CheckMethod::Both;
    return checkReportToJson(plan, checkDocument(plan, options), -1);
  }

 private:
  AssemblyDocument design_;
  PlateDesignSession session_;
};

class FrameSession : public DesignSession {
 public:
  FrameSession(const std::string& text, const std::string& source, const FramePackageOptions& options)
      : frame_(parseFrameText(text, source, options.jointSize)), session_(frame_.layout, options.design) {}

  std::string stateJson() const override { return frameSessionStateToJson(frame_, session_); }
  int childCount() override { return session_.childCount(); }
  std::string previewJson(int child) override { return frameStepToJson(frame_, session_.childPreview(child)); }
  void choose(int child) override { session_.chooseChild(child); }
  bool next() override { return session_.next(); }
  bool back() override { return session_.back(); }
  std::string finishJson(const DesignLimits& limits) override {
    return frameDesignResultToJson(frame_, session_.finish(limits));
  }
  // The verified result once complete (as a whole design's verification), else the frame as given.
  std::string checkJson() const override {
    const AssemblyDocument current = parseAssemblyText(
        session_.complete() ? frameResultToJson(frame_.layout, session_.result(), frame_.name, -1)
                            : frameDocumentToJson(frame_, -1),
        "result");
    return checkReportToJson(current, checkDocument(current, CheckOptions{}), -1);
  }

 private:
  FrameDocument frame_;
  FrameDesignSession session_;
};

std::unique_ptr<DesignSession> openPlateSession(AssemblyDocument design, const std::string& optionsJson) {
  return std::make_unique<PlateSession>(std::move(design), optionsJson);
}

std::unique_ptr<DesignSession> openFrameSession(const std::string& text, const std::string& source,
                                                const std::string& optionsJson) {
  return std::make_unique<FrameSession>(text, source, parseFrameDesignOptionsJson(optionsJson));
}

// A mesh of any orientation as drawable triangles with flat normals.
PartSurface flatSurface(int partId, const TriangleMesh& mesh) {
  PartSurface surface;
  surface.partId = partId;
  for (const std::array<int, 3>& triangle : mesh.triangles) {
    const std::array<double, 3>& a = mesh.vertices[triangle[0]];
    const std::array<double, 3>& b = mesh.vertices[triangle[1]];
    const std::array<double, 3>& c = mesh.vertices[triangle[2]];
    double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                   (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                   (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = length > 0 ? x / length : 0;
    for (const std::array<double, 3>* vertex : {&a, &b, &c}) {
      for (int k = 0; k < 3; ++k) {
        surface.positions.push_back(static_cast<float>((*vertex)[k]));
        surface.normals.push_back(static_cast<float>(n[k]));
      }
    }
  }
  return surface;
}

std::vector<PartSurface> plateSurfaces(const AssemblyDocument& document) {
  std::vector<PartSurface> surfaces;
  for (const Plate& plate : document.plates) surfaces.push_back(flatSurface(plate.id, plateSolidMesh(plate)));
  return surfaces;
}

std::vector<PartSurface> frameSurfaces(const AssemblyDocument& document, const std::string& source) {
  return framePartSurfaces(frameFromAssemblyDocument(document, source));
}

std::vector<uint8_t> bytesOf(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

// Plates (in mm) as closed meshes, one per plate, `part` 0 for all. The kind picks its meshes here.
std::vector<uint8_t> exportPlates(const AssemblyDocument& document, ExportFormat format, const ExportOptions& options) {
  if (format == ExportFormat::XmPuzzle) {
    throwBadInput(options.source, "BurrTools .xmpuzzle holds voxel puzzles; export plates as stl, stl-ascii or obj");
  }
  if (format == ExportFormat::BuildPlateStl) {
    throwBadInput(options.source, "a build plate lays out voxel parts; plates are laid flat on cut sheets (svg, dxf)");
  }
  if (options.clearance != 0) {
    throwBadInput(options.source, "plates take their clearance when they are designed (desia design plate --clearance), "
                                  "not when they are exported");
  }
  std::vector<NamedMesh> meshes;
  // A result cut with a clearance: the plates to make (their mortises larger), not the verified ones.
  for (const Plate& plate : document.fabricationPlates.empty() ? document.plates : document.fabricationPlates) {
    if (options.part == 0 || options.part == plate.id) meshes.push_back({plate.id, plateSolidMesh(plate), ""});
  }
  if (meshes.empty()) throwBadInput(options.source, "part " + std::to_string(options.part) + " is not a plate of this structure (0 = all plates)");
  const std::string title = "plate export, " + (options.part == 0 ? std::to_string(meshes.size()) + " plates" : "plate " + std::to_string(options.part)) + ", mm";
  std::string bytes;
  switch (format) {
    case ExportFormat::StlBinary: bytes = binaryStl(meshes, title); break;
    case ExportFormat::StlAscii: bytes = asciiStl(meshes, options.part == 0 ? "structure" : "plate" + std::to_string(options.part)); break;
    case ExportFormat::Obj: bytes = wavefrontObj(meshes, title); break;
    case ExportFormat::StlZip: {
      int largestId = 0;
      for (const NamedMesh& mesh : meshes) largestId = std::max(largestId, mesh.partId);
      return stlZipArchive(meshes, largestId, "plate export, mm");
    }
    case ExportFormat::XmPuzzle:
    case ExportFormat::BuildPlateStl: break;
  }
  return bytesOf(bytes);
}

std::vector<std::string> cutSheets(const AssemblyDocument& document, const std::string& format,
                                   const CutSheetOptions& options) {
  return plateCutSheets(document, parseCutFileFormat(format), options);
}

std::vector<uint8_t> exportFrameFiles(const AssemblyDocument& document, const std::string& format, int part,
                                      const std::string& source) {
  return exportFrame(frameFromAssemblyDocument(document, source), format, part, source);
}

constexpr PlateFrameEntries kEntries = [] {
  PlateFrameEntries entries{};
  entries.frameFromJson = &frameAssemblyDocumentFromJson;
  entries.frameFromFpuz = &frameAssemblyDocumentFromFpuz;
  entries.plateDesignFromJson = &plateDesignFromJson;
  entries.readPlanPlates = &readPlanPlates;
  entries.frameSections = &frameSectionsJson;
  entries.platesJson = &platesToJson;
  entries.checkPlateResult = &checkPlateResult;
  entries.frameShapeRemoval = &frameShapeRemoval;
  entries.openPlateSession = &openPlateSession;
  entries.openFrameSession = &openFrameSession;
  entries.cutSheets = &cutSheets;
  entries.exportFrame = &exportFrameFiles;
  entries.exportPlates = &exportPlates;
  entries.plateSurfaces = &plateSurfaces;
  entries.frameSurfaces = &frameSurfaces;
  return entries;
}();

}  // namespace

const PlateFrameEntries& plateFrameEntries() { return kEntries; }

}  // namespace desia
