// SPDX-License-Identifier: GPL-3.0-or-later
// embind adapter of both WebAssembly modules (the light one: voxels, contacts, meshes; the full
// one adds bindings_plate_frame.cpp): small free functions converting between JS values and the core API. No
// algorithm lives here. Results cross the boundary as plain JS objects (JSON text parsed on the
// JS side of this call), and every C++ exception becomes a real JS Error carrying the core's
// message and a `code` ("bad-input", "too-large", "unsupported", "internal").
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/mesh.h"
#include "desia/version.h"
#include "desia/voxel.h"
#include "bindings_common.h"

namespace {

using emscripten::val;
using desia::bindings::guarded;
using desia::bindings::listen;
using desia::bindings::parseJsonText;

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
    listen(options.limits, onProgress);
    return parseJsonText(desia::designResultToJson(desia::designVoxelPuzzle(document.voxels, options)));
  });
}

// The interactive design session (a long-lived handle: JS must call delete(), which the facade's
// dispose() does), for a voxel shape, a plate design or a frame (desia/design_io.h: the kind
// of the document decides). Every method returns plain data.
class DesignSession {
 public:
  DesignSession(const std::string& text, const std::string& optionsJson, const std::string& source) {
    guarded([&] { session_ = desia::openDesignSession(text, optionsJson, source); });
  }

  val state() const { return guarded([&] { return parseJsonText(session_->stateJson()); }); }
  int childCount() { return guarded([&] { return session_->childCount(); }); }
  val preview(int n) { return guarded([&] { return parseJsonText(session_->previewJson(n)); }); }
  void choose(int n) { guarded([&] { session_->choose(n); }); }
  bool next() { return guarded([&] { return session_->next(); }); }
  bool back() { return guarded([&] { return session_->back(); }); }
  // "Finish automatically from here": the designer's search below the current node; the same
  // result object as designVoxel / designPlate / designFrame, with their onProgress.
  val finish(const std::string& limitsJson, val onProgress) {
    return guarded([&] {
      desia::DesignLimits limits = desia::parseDesignLimitsJson(limitsJson);
      listen(limits, onProgress);
      return parseJsonText(session_->finishJson(limits));
    });
  }
  val check() const { return guarded([&] { return parseJsonText(session_->checkJson()); }); }

 private:
  std::unique_ptr<desia::DesignSession> session_;
};

// An assembly (voxel .puz or JSON text, a plate structure or a frame) as the bytes of one file in
// `format` (desia/export.h: the same registry and writers as the CLI's export); part 0 =
// all parts; `spacing` NaN = the default (one voxel). Cut sheets come from cutSheets. Returns a
// Uint8Array that owns its bytes (copied out of the heap at once: a later memory growth would
// detach a view, toolchain.md #9).
val exportAssembly(const std::string& text, const std::string& format, int part, double voxelSize, double clearance,
                   double spacing, const std::string& source) {
  return guarded([&] {
    desia::ExportSettings settings;
    settings.mesh.part = part;
    settings.mesh.voxelSizeFromDocument = std::isnan(voxelSize);  // not given: the .puz file's, else 1
    if (!settings.mesh.voxelSizeFromDocument) settings.mesh.voxelSize = voxelSize;
    settings.mesh.clearance = clearance;
    if (!std::isnan(spacing)) settings.mesh.spacing = spacing;
    settings.mesh.source = source;
    const desia::ExportFormatInfo& info = desia::exportFormatNamed(format);
    const std::string bytes = desia::exportFiles(desia::parseAssemblyText(text, source), info, settings).front();
    return val(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()))).call<val>("slice");
  });
}

// The export-format registry as plain data: [{ name, kinds, options, perSheet, what }].
val exportFormats() {
  return guarded([&] {
    val formats = val::array();
    for (const desia::ExportFormatInfo& info : desia::exportFormats()) {
      val format = val::object();
      format.set("name", std::string(info.name));
      val kinds = val::array();
      for (desia::AssemblyKind kind : info.kinds) kinds.call<void>("push", std::string(desia::assemblyKindName(kind)));
      format.set("kinds", kinds);
      val options = val::array();
      for (desia::ExportOptionGroup option : info.options) options.call<void>("push", std::string(desia::exportOptionGroupName(option)));
      format.set("options", options);
      format.set("perSheet", info.perSheet);
      format.set("what", std::string(info.what));
      formats.call<void>("push", format);
    }
    return formats;
  });
}

// Part surfaces as an array of { partId, positions, normals } with Float32Arrays owning their floats
// (copied out of the heap at once, like exportAssembly's bytes).
val surfacesToJs(const std::vector<desia::PartSurface>& surfaces) {
  val result = val::array();
  for (const desia::PartSurface& surface : surfaces) {
    val part = val::object();
    part.set("partId", surface.partId);
    part.set("positions", val(emscripten::typed_memory_view(surface.positions.size(), surface.positions.data())).call<val>("slice"));
    part.set("normals", val(emscripten::typed_memory_view(surface.normals.size(), surface.normals.data())).call<val>("slice"));
    result.call<void>("push", part);
  }
  return result;
}

// The surface of every part of an assembly (.puz or JSON text; plates and frames in the full module), ready to draw: an array of
// { partId, positions, normals } with Float32Arrays owning their floats (copied out of the heap at
// once, like exportAssembly's bytes).
val partSurfaces(const std::string& text, const std::string& source) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    return surfacesToJs(desia::partSurfaces(document, source));
  });
}

// Mesh files from the facade: parallel arrays of names and Uint8Arrays (core.js turns text into
// bytes), each read into a string with the same size cap as voxelize's mesh.
std::vector<desia::MeshFile> meshFilesFrom(const val& names, const val& contents) {
  std::vector<desia::MeshFile> files;
  const int count = names["length"].as<int>();
  for (int k = 0; k < count; ++k) {
    const std::string name = names[k].as<std::string>();
    files.push_back({name, bytesFromUint8Array(contents[k], name)});
  }
  return files;
}

// A mesh assembly (issue 29) checked as `desia check FILES --unit U --tolerance T --json` checks
// it: the same core call (checkMeshFiles) and report writer. `tolerance` 0 = the default.
val checkMeshes(const val& names, const val& contents, const std::string& unit, double tolerance,
                const std::string& method, bool allGraphs) {
  return guarded([&] {
    desia::CheckOptions options;
    options.method = desia::parseCheckMethod(method);
    options.allGraphs = allGraphs;
    desia::MeshAssemblyOptions meshOptions;
    meshOptions.contactTolerance = tolerance;
    const desia::MeshCheck check =
        desia::checkMeshFiles(meshFilesFrom(names, contents), desia::parseLengthUnit(unit), meshOptions, options);
    return parseJsonText(desia::meshCheckReportToJson(check.meshes, check.report, -1));
  });
}

// The parts of mesh files to draw, as partSurfaces (millimetres).
val meshSurfaces(const val& names, const val& contents, const std::string& unit) {
  return guarded([&] {
    return surfacesToJs(desia::meshPartSurfaces(meshFilesFrom(names, contents), desia::parseLengthUnit(unit)));
  });
}

std::string version() { return desia::kVersion; }

}  // namespace

// Both modules (docs/architecture.md, "Two WebAssembly modules"); the full one adds
// bindings_plate_frame.cpp.
EMSCRIPTEN_BINDINGS(desia) {
  emscripten::function("check", &check);
  emscripten::function("parseDocument", &parseDocument);
  emscripten::function("toPuz", &toPuz);
  emscripten::function("voxelize", &voxelize);
  emscripten::function("designVoxel", &designVoxel);
  emscripten::function("exportAssembly", &exportAssembly);
  emscripten::function("exportFormats", &exportFormats);
  emscripten::function("partSurfaces", &partSurfaces);
  emscripten::function("checkMeshes", &checkMeshes);
  emscripten::function("meshSurfaces", &meshSurfaces);
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
