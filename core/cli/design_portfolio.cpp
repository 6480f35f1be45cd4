// SPDX-License-Identifier: GPL-3.0-or-later
// The voxel designer's search is heavy tailed (docs/voxel.md, "Restarts"): how long a seed takes varies by
// orders of magnitude, so independent searches from several seeds, the first verified one
// winning, use extra cores well. Each search is the single-threaded core, unchanged and
// re-entrant (no global mutable state), so the winner's puzzle is exactly the one a single
// search with its seed gives: cancelling the others never touches it.
#include "design_portfolio.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace desia::cli {

int defaultDesignJobs() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

namespace {

class Portfolio {
 public:
  Portfolio(const VoxelDesignOptions& options, int jobs)
      : options_(options), progress_(static_cast<size_t>(jobs)), results_(static_cast<size_t>(jobs)),
        errors_(static_cast<size_t>(jobs)) {}

  VoxelDesignResult run(const VoxelGrid& shape) {
    std::vector<std::thread> threads;
    for (size_t job = 0; job < results_.size(); ++job) threads.emplace_back([this, &shape, job] { runJob(shape, job); });
    for (std::thread& thread : threads) thread.join();
    for (const std::exception_ptr& error : errors_) {
      if (error) std::rethrow_exception(error);
    }
    return winner_ >= 0 ? results_[static_cast<size_t>(winner_)] : results_[deepestJob()];
  }

 private:
  // Job k searches from seed + k and reports to the portfolio instead of the caller.
  void runJob(const VoxelGrid& shape, size_t job) {
    VoxelDesignOptions options = options_;
    options.seed = options_.seed + job;
    options.limits.onProgress = [this, job](const DesignProgress& progress) { return onJobProgress(job, progress); };
    try {
      VoxelDesignResult result = designVoxelPuzzle(shape, options);
      std::lock_guard<std::mutex> lock(mutex_);
      if (result.status == DesignStatus::Success && winner_ < 0) {
        winner_ = static_cast<int>(job);
        stop_ = true;  // the others stop at their next node
      }
      results_[job] = std::move(result);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      errors_[job] = std::current_exception();
      stop_ = true;
    }
  }

  bool onJobProgress(size_t job, const DesignProgress& progress) {
    if (stop_) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    progress_[job] = progress;
    if (options_.limits.onProgress && !options_.limits.onProgress(combinedProgress())) stop_ = true;
    return !stop_;
  }

  // What the caller sees: the work of all searches, the depths of the deepest one.
  DesignProgress combinedProgress() const {
    DesignProgress combined = progress_[deepestOf(progress_)];
    combined.nodes = 0;
    for (const DesignProgress& progress : progress_) {
      combined.nodes += progress.nodes;
      combined.seconds = std::max(combined.seconds, progress.seconds);
    }
    return combined;
  }

  size_t deepestJob() const {
    std::vector<DesignProgress> finals;
    for (const VoxelDesignResult& result : results_) finals.push_back(result.progress);
    return deepestOf(finals);
  }

  // The entry with the deepest node (then the deeper current node), the first among equals.
  static size_t deepestOf(const std::vector<DesignProgress>& progress) {
    size_t best = 0;
    for (size_t k = 1; k < progress.size(); ++k) {
      const DesignProgress &p = progress[k], &b = progress[best];
      if (p.bestDepth > b.bestDepth || (p.bestDepth == b.bestDepth && p.depth > b.depth)) best = k;
    }
    return best;
  }

  const VoxelDesignOptions& options_;
  std::mutex mutex_;
  std::atomic<bool> stop_{false};
  int winner_ = -1;
  std::vector<DesignProgress> progress_;
  std::vector<VoxelDesignResult> results_;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace

VoxelDesignResult designVoxelPortfolio(const VoxelGrid& shape, const VoxelDesignOptions& options, int jobs) {
  if (jobs <= 1) return designVoxelPuzzle(shape, options);
  return Portfolio(options, jobs).run(shape);
}

}  // namespace desia::cli
