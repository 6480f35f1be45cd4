// SPDX-License-Identifier: GPL-3.0-or-later
// embind adapter: small free functions converting between JS values and the core API. No
// algorithm lives here. Results cross the boundary as plain JS objects (JSON text parsed on the
// JS side of this call), and every C++ exception becomes a real JS Error carrying the core's
// message and a `code` ("bad-input", "too-large", "unsupported", "internal").
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "desia/check.h"
#include "desia/document_check.h"
#include "desia/cut_sheets.h"
#include "desia/plate_design.h"
#include "desia/plate_design_io.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/frame_design.h"
#include "desia/frame_design_io.h"
#include "desia/frame_format.h"
#include "desia/puz_format.h"
#include "desia/mesh.h"
#include "desia/version.h"
#include "desia/voxelize.h"

namespace {

using emscripten::val;

val parseJsonText(const std::string& text) { return val::global("JSON").call<val>("parse", val(text)); }

// Runs `operation` and converts any exception into a thrown JS Error carrying the core's message
// and a `code`. The JS throw happens after the catch block has ended, so C++ destructors and
// exception cleanup have run (toolchain.md #8).
template <typename Operation>
auto guarded(Operation&& operation) -> decltype(operation()) {
  std::string message, code;
  try {
    return operation();
  } catch (const desia::Error& e) {
    message = e.what();
    code = desia::errorCodeName(e.code());
  } catch (const std::bad_alloc&) {
    message = "out of memory";
    code = "too-large";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
    code = "internal";
  } catch (...) {
    message = "internal error: unknown exception";
    code = "internal";
  }
  val error = val::global("Error").new_(val(message));
  error.set("code", val(code));
  error.set("name", val(std::string("DesiaError")));
  error.throw_();
}

val check(const std::string& text, const std::string& method, const std::string& source, bool allGraphs) {
  return guarded([&] {
    desia::CheckOptions options;
    options.method = desia::parseCheckMethod(method);
    options.allGraphs = allGraphs;
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    return parseJsonText(desia::checkReportToJson(document, desia::checkDocument(document, options), -1));
  });
}

// A voxel assembly (.puz or JSON text) as DESIA .puz text, byte for byte as the original writer.
val toPuz(const std::string& text, const std::string& source) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    if (document.kind != desia::AssemblyKind::Voxel) {
      throw desia::Error(desia::ErrorCode::BadInput, source + ": only voxel assemblies have a .puz form, this is a " +
                                                         std::string(desia::assemblyKindName(document.kind)) + " document");
    }
    return val(desia::formatPuz(document.voxels));
  });
}

val parseDocument(const std::string& text, const std::string& source) {
  return guarded([&] { return parseJsonText(desia::documentToJson(desia::parseAssemblyText(text, source), -1)); });
}

// Copies a JS Uint8Array into a string in one step, the way convertJSArrayToNumberVector does
// (a typed_memory_view's set()), without a second copy through a vector; nothing allocates
// between taking the view and filling it. Same 512 MiB cap as the CLI's file reader.
std::string bytesFromUint8Array(const val& array, const std::string& source) {
  constexpr double kMaxBytes = 512.0 * 1024 * 1024;
  const double length = array["length"].as<double>();
  if (length > kMaxBytes) {
    throw desia::Error(desia::ErrorCode::TooLarge, source + ": the mesh is " +
                                                       std::to_string(static_cast<int64_t>(length)) +
                                                       " bytes, more than the limit of " +
                                                       std::to_string(static_cast<int64_t>(kMaxBytes)) + " bytes");
  }
  std::string bytes(static_cast<size_t>(length), '\0');
  val view(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<uint8_t*>(bytes.data())));
  view.call<void>("set", array);
  return bytes;
}

// OBJ or STL bytes (a Uint8Array) -> the JSON assembly document of the one-part voxel shape.
val voxelize(const val& bytes, int resolution, const std::string& source) {
  return guarded([&] {
    desia::VoxelizeOptions options;
    options.resolution = resolution;
    desia::VoxelGrid grid =
        desia::voxelizeSolid(desia::parseMesh(bytesFromUint8Array(bytes, source), source), options, source);
    return parseJsonText(
        desia::documentToJson(desia::documentFromVoxels(std::move(grid), desia::meshShapeName(source)), -1));
  });
}

// Live design (issue 11): the deepest node found so far rides on a progress object as `snapshot`
// only when it is deeper than the last one handed to JS, so a search of thousands of nodes a
// second copies at most one snapshot per new depth across the boundary.
class SnapshotGate {
 public:
  bool isNew(int depth) {
    if (depth <= sentDepth_) return false;
    sentDepth_ = depth;
    return true;
  }

 private:
  int sentDepth_ = -1;
};

// { depth, labels }: the deepest node's voxel labels (parts 1..depth, depth + 1 the remainder) as
// an Int32Array copied out of the heap, in the shape's grid order (x fastest, as documents).
val voxelSnapshot(const desia::DesignProgress& progress) {
  const std::vector<int>& labels = progress.deepest->labels();
  val snapshot = val::object();
  snapshot.set("depth", progress.bestDepth);
  snapshot.set("labels", val(emscripten::typed_memory_view(labels.size(), labels.data())).call<val>("slice"));
  return snapshot;
}

// { depth, placed }: the plates or beams (input indices, the key first) of the deepest node.
val placedSnapshot(const std::vector<int>& placed) {
  val snapshot = val::object();
  snapshot.set("depth", static_cast<int>(placed.size()));
  snapshot.set("placed", val::array(placed));
  return snapshot;
}

// The voxel designer's progress as a plain object for a JS function, which may return false to stop
// the search. Holds `onProgress` by reference: use it within the call that received it.
std::function<bool(const desia::DesignProgress&)> progressCallback(const val& onProgress) {
  return [&onProgress, gate = SnapshotGate()](const desia::DesignProgress& progress) mutable {
    val value = parseJsonText(desia::designProgressToJson(progress));
    if (progress.deepest && gate.isNew(progress.bestDepth)) value.set("snapshot", voxelSnapshot(progress));
    const val answer = onProgress(value);
    return !(answer.isFalse());
  };
}

// Designs a voxel puzzle. `optionsJson` is the package's options object as JSON text (parsed by the
// core); `onProgress` (a JS function or undefined) receives a plain object after every visited
// node and may return false to stop the search.
val designVoxel(const std::string& shapeText, const std::string& optionsJson, const std::string& source, val onProgress) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(shapeText, source);
    if (document.kind != desia::AssemblyKind::Voxel) {
      throw desia::Error(desia::ErrorCode::BadInput, source + ": designVoxel needs a voxel shape, not a " +
                                                         std::string(desia::assemblyKindName(document.kind)) + " document");
    }
    desia::VoxelDesignOptions options = desia::parseDesignOptionsJson(optionsJson, document.voxels);
    if (onProgress.typeOf().as<std::string>() == "function") {
      options.onProgress = progressCallback(onProgress);
      options.deepestSnapshots = true;  // a listener gets the live view too
    }
    return parseJsonText(desia::designResultToJson(desia::designVoxelPuzzle(document.voxels, options)));
  });
}

// Plans the joints of a plate design (paper Section 5.2); options and progress as for designVoxel.
val designPlate(const std::string& text, const std::string& optionsJson, const std::string& source, val onProgress) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    if (document.kind != desia::AssemblyKind::Plate || !document.contactsFromGeometry) {
      throw desia::Error(desia::ErrorCode::BadInput, source + ": designPlate needs a plate design (kind \"plate\" with \"plates\" and no \"contacts\")");
    }
    desia::PlateDesignOptions options = desia::parsePlateDesignOptionsJson(optionsJson);
    if (onProgress.typeOf().as<std::string>() == "function") {
      options.deepestSnapshots = true;
      options.onProgress = [&onProgress, gate = SnapshotGate()](const desia::PlateDesignProgress& progress) mutable {
        val value = parseJsonText(desia::plateDesignProgressToJson(progress));
        const int placed = static_cast<int>(progress.deepestPlaced.size());
        if (placed > 0 && gate.isNew(placed)) value.set("snapshot", placedSnapshot(progress.deepestPlaced));
        return !(onProgress(value).isFalse());
      };
    }
    return parseJsonText(desia::plateDesignResultToJson(document, desia::designPlateJoints(document.plates, document.plateContacts, options)));
  });
}

// Designs the voxel joints of a frame (paper Section 5.3) from JSON, OBJ or .fpuz text (by the
// extension of `source`); options and progress as for designPlate.
val designFrame(const std::string& text, const std::string& optionsJson, const std::string& source, val onProgress) {
  return guarded([&] {
    desia::FramePackageOptions options = desia::parseFrameDesignOptionsJson(optionsJson);
    const desia::FrameDocument frame = desia::parseFrameText(text, source, options.jointSize);
    if (onProgress.typeOf().as<std::string>() == "function") {
      options.design.deepestSnapshots = true;
      options.design.onProgress = [&onProgress, gate = SnapshotGate()](const desia::FrameDesignProgress& progress) mutable {
        val value = parseJsonText(desia::frameDesignProgressToJson(progress));
        const int placed = static_cast<int>(progress.deepestPlaced.size());
        if (placed > 0 && gate.isNew(placed)) value.set("snapshot", placedSnapshot(progress.deepestPlaced));
        return !(onProgress(value).isFalse());
      };
    }
    return parseJsonText(desia::frameDesignResultToJson(frame, desia::designFrame(frame.layout, options.design)));
  });
}

// A frame from JSON, OBJ or .fpuz text (by the extension of `source`) as its JSON document, checked
// (the frame of an OBJ file's lines and face edges); `jointSize` > 0 overrides the joint cube size.
val parseFrame(const std::string& text, const std::string& source, double jointSize) {
  return guarded([&] { return parseJsonText(desia::frameDocumentToJson(desia::parseFrameText(text, source, jointSize), -1)); });
}

// The interactive design session (a long-lived handle: JS must call delete(), which the facade's
// dispose() does), for a voxel shape, a plate design or a frame (JSON, .fpuz, or OBJ by the
// extension of `source`; the kind of the document decides). Every method returns plain data.
class DesignSession {
 public:
  DesignSession(const std::string& shapeText, const std::string& optionsJson, const std::string& source) {
    guarded([&] {
      const bool obj = source.size() >= 4 && (source.compare(source.size() - 4, 4, ".obj") == 0 ||
                                              source.compare(source.size() - 4, 4, ".OBJ") == 0);
      if (!obj) document_ = desia::parseAssemblyText(shapeText, source);
      if (obj || desia::isFrameDocument(document_)) {
        const desia::FramePackageOptions options = desia::parseFrameDesignOptionsJson(optionsJson);
        frame_ = desia::parseFrameText(shapeText, source, options.jointSize);
        frames_ = std::make_unique<desia::FrameDesignSession>(frame_.layout, options.design);
      } else if (document_.kind == desia::AssemblyKind::Plate && document_.contactsFromGeometry) {
        plates_ = std::make_unique<desia::PlateDesignSession>(document_.plates, document_.plateContacts,
                                                               plateOptions(optionsJson));
      } else if (document_.kind == desia::AssemblyKind::Voxel) {
        voxels_ = std::make_unique<desia::VoxelDesignSession>(document_.voxels, desia::parseDesignOptionsJson(optionsJson, document_.voxels));
      } else {
        throw desia::Error(desia::ErrorCode::BadInput, source + ": a design session needs a voxel shape, a plate design or a frame");
      }
    });
  }

  val state() const {
    return guarded([&] {
      if (frames_) return parseJsonText(desia::frameSessionStateToJson(frame_, *frames_));
      if (plates_) return parseJsonText(desia::plateSessionStateToJson(document_, *plates_));
      val result = val::object();
      result.set("partsPlaced", voxels_->partsPlaced() + 1);  // parts in the current assembly
      result.set("targetParts", voxels_->targetParts());
      result.set("complete", voxels_->complete());
      result.set("document", parseJsonText(desia::documentToJson(desia::documentFromVoxels(voxels_->current()), -1)));
      return result;
    });
  }
  int childCount() {
    return guarded([&] { return frames_ ? frames_->childCount() : plates_ ? plates_->childCount() : voxels_->childCount(); });
  }
  val preview(int n) {
    return guarded([&] {
      if (frames_) return parseJsonText(desia::frameStepToJson(frame_, frames_->childPreview(n)));
      if (plates_) return parseJsonText(desia::plateStepToJson(document_, plates_->childPreview(n)));
      return parseJsonText(desia::documentToJson(desia::documentFromVoxels(voxels_->childPreview(n)), -1));
    });
  }
  void choose(int n) {
    guarded([&] { frames_ ? frames_->chooseChild(n) : plates_ ? plates_->chooseChild(n) : voxels_->chooseChild(n); });
  }
  bool next() { return guarded([&] { return frames_ ? frames_->next() : plates_ ? plates_->next() : voxels_->generateNextPart(); }); }
  bool back() { return guarded([&] { return frames_ ? frames_->back() : plates_ ? plates_->back() : voxels_->goBack(); }); }
  // "Finish automatically from here": the designer's search below the current node; the same
  // result object as designVoxel / designPlate / designFrame, with their onProgress.
  val finish(const std::string& limitsJson, val onProgress) {
    return guarded([&] {
      desia::DesignLimits limits = desia::parseDesignLimitsJson(limitsJson);
      if (frames_) {
        desia::FrameDesignLimits frameLimits;
        frameLimits.timeLimitSeconds = limits.timeLimitSeconds;
        frameLimits.nodeLimit = limits.nodeLimit;
        if (onProgress.typeOf().as<std::string>() == "function") {
          frameLimits.deepestSnapshots = true;
          frameLimits.onProgress = [&onProgress, gate = SnapshotGate()](const desia::FrameDesignProgress& progress) mutable {
            val value = parseJsonText(desia::frameDesignProgressToJson(progress));
            const int placed = static_cast<int>(progress.deepestPlaced.size());
            if (placed > 0 && gate.isNew(placed)) value.set("snapshot", placedSnapshot(progress.deepestPlaced));
            return !(onProgress(value).isFalse());
          };
        }
        return parseJsonText(desia::frameDesignResultToJson(frame_, frames_->finish(frameLimits)));
      }
      if (plates_) {
        desia::PlateDesignLimits plateLimits;
        plateLimits.timeLimitSeconds = limits.timeLimitSeconds;
        plateLimits.nodeLimit = limits.nodeLimit;
        if (onProgress.typeOf().as<std::string>() == "function") {
          plateLimits.deepestSnapshots = true;
          plateLimits.onProgress = [&onProgress, gate = SnapshotGate()](const desia::PlateDesignProgress& progress) mutable {
            val value = parseJsonText(desia::plateDesignProgressToJson(progress));
            const int placed = static_cast<int>(progress.deepestPlaced.size());
            if (placed > 0 && gate.isNew(placed)) value.set("snapshot", placedSnapshot(progress.deepestPlaced));
            return !(onProgress(value).isFalse());
          };
        }
        return parseJsonText(desia::plateDesignResultToJson(document_, plates_->finish(plateLimits)));
      }
      if (onProgress.typeOf().as<std::string>() == "function") {
        limits.onProgress = progressCallback(onProgress);
        limits.deepestSnapshots = true;
      }
      return parseJsonText(desia::designResultToJson(voxels_->finish(limits)));
    });
  }
  val check() const {
    return guarded([&] {
      desia::CheckOptions options;
      if (frames_) {
        // The verified result once complete (as designFrame's verification), else the frame as given.
        const desia::AssemblyDocument current = desia::parseAssemblyText(
            frames_->complete() ? desia::frameResultToJson(frame_.layout, frames_->result(), frame_.name, -1)
                                : desia::frameDocumentToJson(frame_, -1),
            "result");
        return parseJsonText(desia::checkReportToJson(current, desia::checkDocument(current, options), -1));
      }
      if (plates_) {
        // The verified result once complete (both tests, as designPlate), else the design as given.
        const desia::AssemblyDocument current =
            plates_->complete() ? desia::parseJsonDocument(desia::plateDesignToJson(document_, plates_->result(), -1), "plan") : document_;
        if (plates_->complete()) options.method = desia::CheckMethod::Both;
        return parseJsonText(desia::checkReportToJson(current, desia::checkDocument(current, options), -1));
      }
      const desia::AssemblyDocument document = desia::documentFromVoxels(voxels_->current());
      return parseJsonText(desia::checkReportToJson(document, voxels_->check(), -1));
    });
  }

 private:
  static desia::PlateDesignOptions plateOptions(const std::string& optionsJson) { return desia::parsePlateDesignOptionsJson(optionsJson); }

  desia::AssemblyDocument document_;
  desia::FrameDocument frame_;
  std::unique_ptr<desia::VoxelDesignSession> voxels_;
  std::unique_ptr<desia::PlateDesignSession> plates_;
  std::unique_ptr<desia::FrameDesignSession> frames_;
};

// A voxel assembly (.puz or JSON text) as file bytes: "stl", "stl-ascii", "obj", "xmpuzzle",
// "stl-zip" or "build-plate-stl"; part 0 = all parts; `spacing` NaN = the default (one voxel).
// Returns a Uint8Array that owns its bytes (copied out of the heap at once: a later memory growth
// would detach a view, toolchain.md #9).
val exportAssembly(const std::string& text, const std::string& format, int part, double voxelSize, double clearance,
                   double spacing, const std::string& source) {
  return guarded([&] {
    desia::ExportOptions options;
    options.part = part;
    options.voxelSize = voxelSize;
    options.clearance = clearance;
    if (!std::isnan(spacing)) options.spacing = spacing;
    options.source = source;
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    if (desia::isFrameDocument(document) && clearance != 0) {
      throw desia::Error(desia::ErrorCode::BadInput, source + ": the clearance applies to voxel assemblies, not to frames");
    }
    // Frames have their own exports (meshes, .fpuz, the cut list) in the core.
    const std::vector<uint8_t> bytes =
        desia::isFrameDocument(document)
            ? desia::exportFrame(desia::frameFromAssemblyDocument(document, source), format, part, source)
            : desia::exportAssembly(document, desia::parseExportFormat(format), options);
    return val(emscripten::typed_memory_view(bytes.size(), bytes.data())).call<val>("slice");
  });
}

// The surface of every part of a voxel assembly (.puz or JSON text), ready to draw: an array of
// { partId, positions, normals } with Float32Arrays owning their floats (copied out of the heap at
// once, like exportAssembly's bytes).
val partSurfaces(const std::string& text, const std::string& source) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    const std::vector<desia::PartSurface> surfaces =
        desia::isFrameDocument(document) ? desia::framePartSurfaces(desia::frameFromAssemblyDocument(document, source))
                                         : desia::partSurfaces(document, source);
    val result = val::array();
    for (const desia::PartSurface& surface : surfaces) {
      val part = val::object();
      part.set("partId", surface.partId);
      part.set("positions", val(emscripten::typed_memory_view(surface.positions.size(), surface.positions.data())).call<val>("slice"));
      part.set("normals", val(emscripten::typed_memory_view(surface.normals.size(), surface.normals.data())).call<val>("slice"));
      result.call<void>("push", part);
    }
    return result;
  });
}

// The cut files of a plate structure (JSON text): an array of strings, one SVG or DXF per sheet.
val cutSheets(const std::string& text, const std::string& format, const std::string& optionsJson) {
  return guarded([&] {
    const desia::CutSheetOptions options = desia::parseCutSheetOptionsJson(optionsJson);
    const std::vector<std::string> sheets =
        desia::plateCutSheets(desia::parseAssemblyText(text, options.source), desia::parseCutFileFormat(format), options);
    val result = val::array();
    for (const std::string& sheet : sheets) result.call<void>("push", val(sheet));
    return result;
  });
}

std::string version() { return desia::kVersion; }

}  // namespace

EMSCRIPTEN_BINDINGS(desia) {
  emscripten::function("check", &check);
  emscripten::function("parseDocument", &parseDocument);
  emscripten::function("toPuz", &toPuz);
  emscripten::function("voxelize", &voxelize);
  emscripten::function("designVoxel", &designVoxel);
  emscripten::function("designPlate", &designPlate);
  emscripten::function("designFrame", &designFrame);
  emscripten::function("parseFrame", &parseFrame);
  emscripten::function("exportAssembly", &exportAssembly);
  emscripten::function("partSurfaces", &partSurfaces);
  emscripten::function("cutSheets", &cutSheets);
  emscripten::function("version", &version);
  emscripten::class_<DesignSession>("DesignSession")
      .constructor<std::string, std::string, std::string>()
      .function("state", &DesignSession::state)
      .function("childCount", &DesignSession::childCount)
      .function("preview", &DesignSession::preview)
      .function("choose", &DesignSession::choose)
      .function("next", &DesignSession::next)
      .function("back", &DesignSession::back)
      .function("check", &DesignSession::check)
      .function("finish", &DesignSession::finish);
}
