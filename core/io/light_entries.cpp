// SPDX-License-Identifier: GPL-3.0-or-later
// The light WebAssembly module's table (io/kind_entries.h): voxels, contacts and meshes only. Every
// plate and frame entry throws ErrorCode::KindNotBuilt before doing anything, which the package's
// worker (wasm/host.js) answers by loading the full module and asking it the same question.
#include "desia/error.h"
#include "io/kind_entries.h"

namespace desia {
namespace {

[[noreturn]] void throwKindNotBuilt() {
  throw Error(ErrorCode::KindNotBuilt,
              "plates and frames are in the full desia module (dist/desia_wasm.wasm), not in this light one");
}

// The refusing function for a table entry of type `Entry` (a function pointer type).
template <typename Entry>
struct Refuse;

template <typename Result, typename... Arguments>
struct Refuse<Result (*)(Arguments...)> {
  static Result call(Arguments...) { throwKindNotBuilt(); }
};

template <typename Entry>
constexpr Entry refuse(Entry /*type only*/) {
  return &Refuse<Entry>::call;
}

constexpr PlateFrameEntries kEntries = [] {
  PlateFrameEntries entries{};
  entries.frameFromJson = refuse(entries.frameFromJson);
  entries.frameFromFpuz = refuse(entries.frameFromFpuz);
  entries.plateDesignFromJson = refuse(entries.plateDesignFromJson);
  entries.readPlanPlates = refuse(entries.readPlanPlates);
  entries.frameSections = refuse(entries.frameSections);
  entries.platesJson = refuse(entries.platesJson);
  entries.checkPlateResult = refuse(entries.checkPlateResult);
  entries.frameShapeRemoval = refuse(entries.frameShapeRemoval);
  entries.openPlateSession = refuse(entries.openPlateSession);
  entries.openFrameSession = refuse(entries.openFrameSession);
  entries.cutSheets = refuse(entries.cutSheets);
  entries.exportFrame = refuse(entries.exportFrame);
  entries.exportPlates = refuse(entries.exportPlates);
  entries.plateSurfaces = refuse(entries.plateSurfaces);
  entries.frameSurfaces = refuse(entries.frameSurfaces);
  return entries;
}();

}  // namespace

const PlateFrameEntries& plateFrameEntries() { return kEntries; }

}  // namespace desia
