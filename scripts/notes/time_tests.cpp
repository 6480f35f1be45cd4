// Notes tool (issue 10, scale-1500): times the two interlocking tests (paper Section 3.2) on a
// designed voxel puzzle, e.g. the 1500-part 35^3 cube written by `desia design voxel ... --output
// X.puz`, beside desia_bench's "full work" rows on its generated (not interlocking) cube, in the
// same process. Each time includes deriving the contacts from the voxels, as desia_bench's rows
// do. Medians of CPU time (the machine is shared: wall time follows the load).
// g++ -O2 -std=c++17 -Icore/include -Itests/benchmarks scripts/notes/time_tests.cpp \
//   build/native/tests/benchmarks/libdesia_bench_workloads.a build/native/core/libdesia_core.a -lglpk -lpolyclipping
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "desia/blocking_graph.h"
#include "desia/interlocking.h"
#include "desia/puz_format.h"
#include "workloads.h"

namespace {

double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

template <typename F>
double medianMs(int runs, F f) {
  std::vector<double> ms;
  for (int k = 0; k < runs; ++k) {
    const double start = cpuMs();
    f();
    ms.push_back(cpuMs() - start);
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

std::string readFile(const char* path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: time_tests DESIGNED.puz BUNNY_K80.puz\n");
    return 2;
  }
  const desia::VoxelGrid puzzle = desia::parsePuz(readFile(argv[1]));
  const desia::Assembly assembly = desia::assemblyFromVoxels(puzzle);
  std::printf("designed: %d parts, %zu contacts\n", assembly.partCount(), assembly.contacts.size());
  desia::InterlockingResult dbg, lp;
  const double dbgMs = medianMs(15, [&] {
    const desia::Assembly a = desia::assemblyFromVoxels(puzzle);
    dbg = desia::testInterlockingByGraphs(a, desia::buildBaseBlockingGraphs(a));
  });
  const double lpMs = medianMs(7, [&] {
    const desia::Assembly a = desia::assemblyFromVoxels(puzzle);
    lp = desia::testInterlockingByInequalities(a);
  });
  const double contactsMs = medianMs(15, [&] { (void)desia::assemblyFromVoxels(puzzle); });
  std::printf("designed, DBG test: %s (key %d), median %.1f ms CPU\n", desia::verdictName(dbg.verdict), dbg.key, dbgMs);
  std::printf("designed, LP test: %s (key %d), median %.1f ms CPU\n", desia::verdictName(lp.verdict), lp.key, lpMs);
  std::printf("designed, contacts from voxels alone: median %.1f ms CPU\n", contactsMs);
  const std::string levelPuzzle = "tests/data/burrtools/PelikanBurr-p0-s0.puz";  // run from the checkout
  const desia::bench::WorkloadInputs inputs(readFile(argv[2]), argv[2], readFile(levelPuzzle), levelPuzzle);
  for (const char* name : {"cube35-1500 dbg (full work)", "cube35-1500 lp (full work)", "cube35-1500 contacts only"}) {
    const desia::bench::WorkloadSpec& spec = desia::bench::workloadByName(name);
    std::printf("generated, %s: median %.1f ms CPU\n", name,
                medianMs(15, [&] { (void)desia::bench::runWorkload(spec.id, inputs); }));
  }
  return 0;
}
