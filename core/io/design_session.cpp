// SPDX-License-Identifier: GPL-3.0-or-later
// The three kinds' sessions behind one interface (desia/design_io.h).
#include "desia/design_io.h"

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"
#include "desia/voxel.h"

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

bool isObjSource(const std::string& source) {
  return source.size() >= 4 &&
         (source.compare(source.size() - 4, 4, ".obj") == 0 || source.compare(source.size() - 4, 4, ".OBJ") == 0);
}

}  // namespace

std::unique_ptr<DesignSession> openDesignSession(const std::string& text, const std::string& optionsJson,
                                                 const std::string& source) {
  // An OBJ file is a frame's lines (a voxel shape comes voxelized, a plate design as JSON).
  if (isObjSource(source)) return std::make_unique<FrameSession>(text, source, parseFrameDesignOptionsJson(optionsJson));
  AssemblyDocument document = parseAssemblyText(text, source);
  if (isFrameDocument(document)) {
    return std::make_unique<FrameSession>(text, source, parseFrameDesignOptionsJson(optionsJson));
  }
  if (document.kind == AssemblyKind::Plate && document.contactsFromGeometry) {
    return std::make_unique<PlateSession>(std::move(document), optionsJson);
  }
  if (document.kind == AssemblyKind::Voxel) return std::make_unique<VoxelSession>(document, optionsJson);
  throwBadInput(source, "a design session needs a voxel shape, a plate design or a frame");
}

}  // namespace desia
