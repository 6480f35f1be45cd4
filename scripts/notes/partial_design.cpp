// Notes tool (issue 10, scale-1500): designs with a node limit and prints the deepest node's
// depth, an FNV-1a hash of its labels, and the time, so partial 35^3 runs can be compared byte
// for byte between builds. Also prints parts reached per time checkpoint with --checkpoints.
// Build: see scripts/notes/compare_designs.sh.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "desia/puz_format.h"
#include "desia/voxel_design.h"

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: partial_design SHAPE.puz PARTS SEED NODE_LIMIT [TIME_LIMIT]\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  const desia::VoxelGrid shape = desia::parsePuz(text.str());
  desia::VoxelDesignOptions options;
  options.parts = std::atoi(argv[2]);
  options.seed = std::strtoull(argv[3], nullptr, 10);
  options.nodeLimit = std::atoll(argv[4]);
  if (argc > 5) options.timeLimitSeconds = std::atof(argv[5]);
  options.deepestSnapshots = true;
  int lastDepth = 0;
  options.onProgress = [&](const desia::DesignProgress& p) {
    if (p.bestDepth / 50 > lastDepth / 50) std::fprintf(stderr, "depth %d at %.1f s\n", p.bestDepth, p.elapsedSeconds);
    lastDepth = std::max(lastDepth, p.bestDepth);
    return true;
  };
  const desia::VoxelDesignResult result = desia::designVoxelPuzzle(shape, options);
  uint64_t hash = 1469598103934665603ull;
  if (result.progress.deepest) {
    for (int label : result.progress.deepest->labels()) {
      hash = (hash ^ static_cast<uint64_t>(label)) * 1099511628211ull;
    }
  }
  std::printf("status %s depth %d nodes %lld hash %016llx time %.2f s\n", desia::designStatusName(result.status),
              result.progress.bestDepth, static_cast<long long>(result.progress.nodesVisited),
              static_cast<unsigned long long>(hash), result.progress.elapsedSeconds);
  return 0;
}
