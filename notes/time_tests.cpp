// Notes tool (issue 10, scale-1500): times the two interlocking tests (paper Section 3.2) on a
// designed voxel puzzle, e.g. the 1500-part 35^3 cube written by `desia design voxel ... --output
// X.puz`. Each time includes deriving the contacts from the voxels (assemblyFromVoxels), as the
// "full work" rows of desia_bench do; median of several runs.
// g++ -O2 -std=c++17 -Icore/include notes/time_tests.cpp build/native/core/libdesia_core.a -lglpk -lpolyclipping
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "desia/blocking_graph.h"
#include "desia/interlocking.h"
#include "desia/puz_format.h"

template <typename F>
double medianMs(int runs, F f) {
  std::vector<double> ms;
  for (int k = 0; k < runs; ++k) {
    const auto start = std::chrono::steady_clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  const desia::VoxelGrid puzzle = desia::parsePuz(text.str());
  const desia::Assembly assembly = desia::assemblyFromVoxels(puzzle);
  std::printf("%d parts, %zu contacts\n", assembly.partCount(), assembly.contacts.size());
  desia::InterlockingResult dbg, lp;
  const double dbgMs = medianMs(9, [&] {
    const desia::Assembly a = desia::assemblyFromVoxels(puzzle);
    dbg = desia::testInterlockingByGraphs(a, desia::buildBaseBlockingGraphs(a));
  });
  const double lpMs = medianMs(5, [&] {
    const desia::Assembly a = desia::assemblyFromVoxels(puzzle);
    lp = desia::testInterlockingByInequalities(a);
  });
  const double contactsMs = medianMs(9, [&] { (void)desia::assemblyFromVoxels(puzzle); });
  std::printf("DBG test: %s (key %d), median %.1f ms\n", desia::verdictName(dbg.verdict), dbg.key, dbgMs);
  std::printf("LP test: %s (key %d), median %.1f ms\n", desia::verdictName(lp.verdict), lp.key, lpMs);
  std::printf("contacts from voxels alone: median %.1f ms\n", contactsMs);
  return 0;
}
