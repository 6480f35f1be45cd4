// SPDX-License-Identifier: GPL-3.0-or-later
// The full WebAssembly module's bindings beyond bindings.cpp: the plate and frame designers, the
// frame reader and plates' cut files (docs/architecture.md, "Two WebAssembly modules"). The light
// module leaves this file out; the package (wasm/core.js) sends these calls to the full module.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>
#include <vector>

#include "bindings_common.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"

namespace {

using desia::bindings::guarded;
using desia::bindings::listen;
using desia::bindings::parseJsonText;
using emscripten::val;

// Plans the joints of a plate design (paper Section 5.2); options and progress as for designVoxel.
val designPlate(const std::string& text, const std::string& optionsJson, const std::string& source, val onProgress) {
  return guarded([&] {
    const desia::AssemblyDocument document = desia::parseAssemblyText(text, source);
    if (document.kind != desia::AssemblyKind::Plate || !document.contactsFromGeometry) {
      throw desia::Error(desia::ErrorCode::BadInput, source + ": designPlate needs a plate design (kind \"plate\" with \"plates\" and no \"contacts\")");
    }
    desia::PlateDesignOptions options = desia::parsePlateDesignOptionsJson(optionsJson);
    listen(options.limits, onProgress);
    return parseJsonText(desia::plateDesignResultToJson(document, desia::designPlateJoints(document.plates, document.plateContacts, options)));
  });
}

// Designs the voxel joints of a frame (paper Section 5.3) from JSON, OBJ or .fpuz text (by the
// extension of `source`); options and progress as for designPlate.
val designFrame(const std::string& text, const std::string& optionsJson, const std::string& source, val onProgress) {
  return guarded([&] {
    desia::FramePackageOptions options = desia::parseFrameDesignOptionsJson(optionsJson);
    const desia::FrameDocument frame = desia::parseFrameText(text, source, options.jointSize);
    listen(options.design.limits, onProgress);
    return parseJsonText(desia::frameDesignResultToJson(frame, desia::designFrame(frame.layout, options.design)));
  });
}

// A frame from JSON, OBJ or .fpuz text (by the extension of `source`) as its JSON document, checked
// (the frame of an OBJ file's lines and face edges); `jointSize` > 0 overrides the joint cube size.
val parseFrame(const std::string& text, const std::string& source, double jointSize) {
  return guarded([&] { return parseJsonText(desia::frameDocumentToJson(desia::parseFrameText(text, source, jointSize), -1)); });
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

}  // namespace

EMSCRIPTEN_BINDINGS(desia_plate_frame) {
  emscripten::function("designPlate", &designPlate);
  emscripten::function("designFrame", &designFrame);
  emscripten::function("parseFrame", &parseFrame);
  emscripten::function("cutSheets", &cutSheets);
}
