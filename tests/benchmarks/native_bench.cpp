// SPDX-License-Identifier: GPL-3.0-or-later
// desia_bench: the interlocking-test benchmarks of paper Section 3.2, natively, with Google
// Benchmark. After the usual Google Benchmark output it prints a Markdown table with the paper's
// figures beside the medians measured here, and writes them as JSON (default
// build/bench/native.json) so that tests/benchmarks/wasm_bench.mjs can show native and
// WebAssembly side by side.
//
// Own flags (besides every --benchmark_* flag): --desia_bunny=PATH (the 80-part BUNNY .puz),
// --desia_level_puzzle=PATH (BurrTools' PelikanBurr .puz), --desia_json=PATH (where to write the results; empty: do not write).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "workloads.h"

namespace {

using desia::bench::WorkloadInputs;
using desia::bench::WorkloadSpec;

constexpr int kRepetitions = 7;
// Per repetition, Google Benchmark repeats a workload until this much time has passed, so the
// sub-millisecond BUNNY DBG test is averaged over many calls.
constexpr double kMinTimePerRepetitionSeconds = 0.1;
// Workloads flagged slow take seconds per call: one call per repetition, fewer repetitions, so
// that the whole run stays around a minute.
constexpr int kSlowRepetitions = 3;
// The paper's machine (Section 5), printed under the table for context.
constexpr const char* kPaperMachine = "an iMac with a 4.2GHz CPU (paper Section 5)";

struct Options {
  std::string bunnyPath = DESIA_BENCH_DEFAULT_BUNNY;
  std::string levelPuzzlePath = DESIA_BENCH_DEFAULT_LEVEL_PUZZLE;
  std::string jsonPath = DESIA_BENCH_DEFAULT_JSON;
};

// Parses the flags Google Benchmark left in argv; false (after a message) on an unknown flag.
bool parseOptions(int argc, char** argv, Options* options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto valueOf = [&](const std::string& flag) -> std::optional<std::string> {
      if (arg.rfind(flag + "=", 0) == 0) return arg.substr(flag.size() + 1);
      return std::nullopt;
    };
    if (auto v = valueOf("--desia_bunny")) {
      options->bunnyPath = *v;
    } else if (auto v = valueOf("--desia_level_puzzle")) {
      options->levelPuzzlePath = *v;
    } else if (auto v = valueOf("--desia_json")) {
      options->jsonPath = *v;
    } else {
      std::cerr << "desia_bench: unknown argument " << arg << "\n";
      return false;
    }
  }
  return true;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// What one workload measured: the real (wall) time per call of each repetition.
struct Measured {
  std::vector<double> repetitionMs;
  int64_t iterationsPerRepetition = 0;
  std::string error;
};

// Median over repetitions, computed here (not taken from Google Benchmark's aggregate) so that
// it is defined the same way as in wasm_bench.mjs, and also for a single repetition.
double medianOf(std::vector<double> values) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

// The console reporter, plus a copy of every result keyed by workload name.
class CapturingReporter : public benchmark::ConsoleReporter {
 public:
  // Colours only on a terminal (the default reporter's --benchmark_color=auto does the same).
  CapturingReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  bool ReportContext(const Context& context) override {
    cpus_ = context.cpu_info.num_cpus;
    mhz_ = context.cpu_info.cycles_per_second / 1e6;
    return ConsoleReporter::ReportContext(context);
  }

  // Keeps every run, but shows only the aggregates (and errors) on the console: the effect of
  // DisplayAggregatesOnly, which would also hide the single repetitions from this reporter.
  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> shown;
    for (const Run& run : runs) {
      capture(run);
      if (run.run_type == Run::RT_Aggregate || run.error_occurred) shown.push_back(run);
    }
    if (!shown.empty()) ConsoleReporter::ReportRuns(shown);
  }

  const std::map<std::string, Measured>& results() const { return results_; }
  std::string machine() const {
    std::ostringstream out;
    out << cpus_ << " CPUs at " << static_cast<int>(mhz_) << " MHz";
    return out.str();
  }

 private:
  void capture(const Run& run) {
    Measured& measured = results_[run.run_name.function_name];
    if (run.error_occurred) {
      measured.error = run.error_message;
    } else if (run.run_type == Run::RT_Iteration) {
      measured.repetitionMs.push_back(run.GetAdjustedRealTime());
      measured.iterationsPerRepetition = run.iterations;
    }
  }

  std::map<std::string, Measured> results_;
  int cpus_ = 0;
  double mhz_ = 0;
};

// One untimed call per workload before measuring: a wrong verdict stops everything with a
// clear message instead of producing timings of wrong code. Slow workloads check no verdict.
bool verifyWorkloads(const WorkloadInputs& inputs) {
  for (const WorkloadSpec& spec : desia::bench::workloadSpecs()) {
    if (spec.slow) continue;
    try {
      desia::bench::runWorkload(spec.id, inputs);
    } catch (const std::exception& e) {
      std::cerr << "desia_bench: error: workload \"" << spec.name << "\" failed: " << e.what() << "\n";
      return false;
    }
  }
  return true;
}

// The benchmark body: a wrong verdict (WrongVerdict) ends the benchmark as an error.
void timeWorkload(benchmark::State& state, desia::bench::Workload id, const WorkloadInputs& inputs) {
  for (auto _ : state) {
    try {
      benchmark::DoNotOptimize(desia::bench::runWorkload(id, inputs));
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
  }
}

void registerWorkloads(const WorkloadInputs& inputs) {
  for (const WorkloadSpec& spec : desia::bench::workloadSpecs()) {
    const desia::bench::Workload id = spec.id;
    auto* benchmark = benchmark::RegisterBenchmark(
        spec.name, [id, &inputs](benchmark::State& state) { timeWorkload(state, id, inputs); });
    benchmark->Unit(benchmark::kMillisecond)->UseRealTime();
    if (spec.slow) {
      benchmark->Iterations(1)->Repetitions(kSlowRepetitions);
    } else {
      benchmark->MinTime(kMinTimePerRepetitionSeconds)->Repetitions(kRepetitions);
    }
  }
}

std::string formatMs(double ms) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ms < 10 ? "%.3f ms" : (ms < 1000 ? "%.1f ms" : "%.0f ms"), ms);
  return buffer;
}

// "3.1x faster" / "2.0x slower": the paper's time over ours.
std::string formatSpeedUp(double paperMs, double oursMs) {
  if (paperMs < 0 || !(oursMs > 0)) return "—";
  const double ratio = paperMs / oursMs;
  char buffer[32];
  if (ratio >= 1) {
    std::snprintf(buffer, sizeof buffer, "%.1fx faster", ratio);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.1fx slower", 1 / ratio);
  }
  return buffer;
}

// The cell of one workload: its median, with the repetition count when it differs from the rest.
std::string nativeCell(const WorkloadSpec& spec, const std::map<std::string, Measured>& results, double* medianMs) {
  *medianMs = NAN;
  const auto found = results.find(spec.name);
  if (found == results.end()) return "not run";
  if (!found->second.error.empty()) return "error";
  *medianMs = medianOf(found->second.repetitionMs);
  std::string cell = formatMs(*medianMs);
  const size_t count = found->second.repetitionMs.size();
  if (count != static_cast<size_t>(kRepetitions))
    cell += " (" + std::to_string(count) + (count == 1 ? " rep)" : " reps)");
  return cell;
}

void printTable(const std::map<std::string, Measured>& results, const std::string& machine) {
  std::cout << "\n| workload | paper | desia native (median) | speed-up vs paper |\n"
            << "| --- | ---: | ---: | --- |\n";
  for (const WorkloadSpec& spec : desia::bench::workloadSpecs()) {
    double oursMs = NAN;
    const std::string ours = nativeCell(spec, results, &oursMs);
    std::cout << "| " << spec.name << " | " << (spec.paperMs < 0 ? "—" : formatMs(spec.paperMs)) << " | " << ours
              << " | " << formatSpeedUp(spec.paperMs, oursMs) << " |\n";
  }
  std::cout << "\nMedian of " << kRepetitions << " repetitions (each the mean of the calls that fit in "
            << kMinTimePerRepetitionSeconds << " s), slow rows one call per repetition. Wall time.\n"
            << "Paper: " << kPaperMachine << ". Here: " << machine << ", one thread.\n"
            << "The generated cube is not interlocking: \"full work\" rows time every step an interlocking\n"
            << "verdict needs (no early exit); \"check\" is what the DBG test really costs on it.\n";
}

nlohmann::json resultsToJson(const std::map<std::string, Measured>& results, const std::string& machine,
                             const desia::bench::GridStats& cube) {
  nlohmann::json workloads = nlohmann::json::array();
  for (const WorkloadSpec& spec : desia::bench::workloadSpecs()) {
    const auto found = results.find(spec.name);
    if (found == results.end() || !found->second.error.empty()) continue;
    workloads.push_back({{"name", spec.name},
                         {"paperMs", spec.paperMs < 0 ? nlohmann::json(nullptr) : nlohmann::json(spec.paperMs)},
                         {"medianMs", medianOf(found->second.repetitionMs)},
                         {"repetitionMs", found->second.repetitionMs},
                         {"iterationsPerRepetition", found->second.iterationsPerRepetition}});
  }
  return {{"target", "native"},
          {"machine", machine},
          {"cube",
           {{"parts", cube.parts},
            {"voxels", cube.voxels},
            {"contacts", cube.contacts},
            {"fingerprint", cube.fingerprint}}},
          {"workloads", workloads}};
}

void writeJson(const std::string& path, const nlohmann::json& document) {
  const std::filesystem::path file(path);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  out << document.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  std::cout << "Native results written to " << path << "\n";
}

bool anyError(const std::map<std::string, Measured>& results) {
  for (const auto& [name, measured] : results) {
    if (!measured.error.empty()) {
      std::cerr << "desia_bench: error: \"" << name << "\": " << measured.error << "\n";
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  Options options;
  if (!parseOptions(argc, argv, &options)) return 2;
  std::optional<WorkloadInputs> inputs;
  try {
    inputs.emplace(readFile(options.bunnyPath), options.bunnyPath, readFile(options.levelPuzzlePath), options.levelPuzzlePath);
  } catch (const std::exception& e) {
    std::cerr << "desia_bench: error: preparing the inputs: " << e.what() << "\n";
    return 2;
  }
  const desia::bench::GridStats cube = desia::bench::gridStats(inputs->cube());
  std::cout << desia::bench::describeStats("bunny-80 (" + options.bunnyPath + ")",
                                           desia::bench::gridStats(inputs->bunny()))
            << "\n"
            << desia::bench::describeStats("cube35-1500 (generated)", cube) << "\n\n";
  if (!verifyWorkloads(*inputs)) return 1;

  registerWorkloads(*inputs);
  CapturingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (anyError(reporter.results())) return 1;

  printTable(reporter.results(), reporter.machine());
  try {
    if (!options.jsonPath.empty())
      writeJson(options.jsonPath, resultsToJson(reporter.results(), reporter.machine(), cube));
  } catch (const std::exception& e) {
    std::cerr << "desia_bench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
