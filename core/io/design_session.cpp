// SPDX-License-Identifier: GPL-3.0-or-later
// The three kinds' sessions behind one interface (desia/design_io.h): voxels here, plates and
// frames from the build's table (io/kind_entries.h).
#include "desia/design_io.h"

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/voxel.h"
#include "io/kind_entries.h"

namespace desia {
namespace {

using nlohmann::json;

class VoxelSession : public DesignSession {
 public:
  VoxelSession(const AssemblyDocument& shape, const std::string& optionsJson)
      : session_(shape.voxels, parseDesignOptionsJson(optionsJson, shape.voxels)) {}

  std::string stateJson() const override {
    return json{{"partsPlaced", session_.partsPlaced() + 1},  // parts in the current assembly
                {"targetParts", session_.targetParts()},
                {"complete", session_.complete()},
                {"document", json::parse(documentToJson(documentFromVoxels(session_.current()), -1))}}
        .dump();
  }
  int childCount() override { return session_.childCount(); }
  std::string previewJson(int child) override {
    return documentToJson(documentFromVoxels(session_.childPreview(child)), -1);
  }
  void choose(int child) override { session_.chooseChild(child); }
  bool next() override { return session_.generateNextPart(); }
  bool back() override { return session_.goBack(); }
  std::string finishJson(const DesignLimits& limits) override { return designResultToJson(session_.finish(limits)); }
  std::string checkJson() const override {
    return checkReportToJson(documentFromVoxels(session_.current()), session_.check(), -1);
  }

 private:
  VoxelDesignSession session_;
};

bool isObjSource(const std::string& source) {
  return source.size() >= 4 &&
         (source.compare(source.size() - 4, 4, ".obj") == 0 || source.compare(source.size() - 4, 4, ".OBJ") == 0);
}

}  // namespace

std::unique_ptr<DesignSession> openDesignSession(const std::string& text, const std::string& optionsJson,
                                                 const std::string& source) {
  // An OBJ file is a frame's lines (a voxel shape comes voxelized, a plate design as JSON).
  const PlateFrameEntries& kinds = plateFrameEntries();
  if (isObjSource(source)) return kinds.openFrameSession(text, source, optionsJson);
  AssemblyDocument document = parseAssemblyText(text, source);
  if (isFrameDocument(document)) return kinds.openFrameSession(text, source, optionsJson);
  if (document.kind == AssemblyKind::Plate && document.contactsFromGeometry) {
    return kinds.openPlateSession(std::move(document), optionsJson);
  }
  if (document.kind == AssemblyKind::Voxel) return std::make_unique<VoxelSession>(document, optionsJson);
  throwBadInput(source, "a design session needs a voxel shape, a plate design or a frame");
}

}  // namespace desia
