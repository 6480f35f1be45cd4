// SPDX-License-Identifier: GPL-3.0-or-later
// embind module for the WebAssembly side of the interlocking-test benchmarks (paper Section 3.2):
// the same workloads.cpp as the native desia_bench, driven from node by wasm_bench.mjs.
//   prepare(bunnyPuzText, source, levelPuzzleText, levelPuzzleSource) -> { bunny: stats, cube: stats }   (untimed)
//   workloads()                   -> [{ name, paperMs, measures, slow }]
//   run(name, runs)               -> [milliseconds of each run]
// Each run is timed in C++ with std::chrono::steady_clock (performance.now() underneath), so the
// timed region is exactly the native one, with no JS <-> wasm crossing inside it.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <chrono>
#include <memory>
#include <string>

#include "workloads.h"

namespace {

using emscripten::val;
namespace bench = desia::bench;

std::unique_ptr<bench::WorkloadInputs> gInputs;

// Runs `operation`; any C++ exception becomes a JS Error thrown after the catch block has ended,
// so destructors have run (toolchain.md #8: otherwise JS sees a bare number).
template <typename Operation>
val guarded(Operation&& operation) {
  std::string message;
  try {
    return operation();
  } catch (const std::exception& e) {
    message = e.what();
  } catch (...) {
    message = "unknown C++ exception";
  }
  val::global("Error").new_(val(message)).throw_();
  return val::undefined();  // not reached: throw_ does not return
}

val statsToJs(const bench::GridStats& stats) {
  val out = val::object();
  out.set("parts", stats.parts);
  out.set("voxels", static_cast<double>(stats.voxels));
  out.set("contacts", stats.contacts);
  out.set("smallestPart", static_cast<double>(stats.smallestPart));
  out.set("largestPart", static_cast<double>(stats.largestPart));
  out.set("fingerprint", static_cast<double>(stats.fingerprint));
  return out;
}

val prepare(const std::string& bunnyPuzText, const std::string& source, const std::string& levelPuzzleText,
            const std::string& levelPuzzleSource) {
  return guarded([&] {
    gInputs = std::make_unique<bench::WorkloadInputs>(bunnyPuzText, source, levelPuzzleText, levelPuzzleSource);
    val out = val::object();
    out.set("bunny", statsToJs(bench::gridStats(gInputs->bunny())));
    out.set("cube", statsToJs(bench::gridStats(gInputs->cube())));
    return out;
  });
}

val workloads() {
  val list = val::array();
  for (const bench::WorkloadSpec& spec : bench::workloadSpecs()) {
    val item = val::object();
    item.set("name", std::string(spec.name));
    item.set("paperMs", spec.paperMs < 0 ? val::null() : val(spec.paperMs));
    item.set("measures", std::string(spec.measures));
    item.set("slow", spec.slow);
    list.call<void>("push", item);
  }
  return list;
}

val run(const std::string& name, int runs) {
  return guarded([&] {
    if (!gInputs) throw std::logic_error("call prepare() before run()");
    const bench::WorkloadSpec& spec = bench::workloadByName(name);
    val times = val::array();
    for (int i = 0; i < runs; ++i) {
      const auto start = std::chrono::steady_clock::now();
      bench::runWorkload(spec.id, *gInputs);  // allocates and may throw: never optimised away
      const auto stop = std::chrono::steady_clock::now();
      times.call<void>("push", std::chrono::duration<double, std::milli>(stop - start).count());
    }
    return times;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(desia_bench) {
  emscripten::function("prepare", &prepare);
  emscripten::function("workloads", &workloads);
  emscripten::function("run", &run);
}
