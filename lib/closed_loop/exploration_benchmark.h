#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "closed_loop/exploration_config.h"
#include "closed_loop/exploration_report.h"

namespace stereonav {

// K generated worlds x S seeds, each explored once (issue 18's benchmark).
struct ExplorationBenchmarkJob {
  std::vector<unsigned> world_seeds;  // simulator/world_generator.h
  std::vector<int> run_seeds;         // ExplorationJob::seed: noise and start
  std::string output_directory;       // must exist
  std::optional<double> max_time_s;   // default: [simulation] max_duration_s
  size_t parallel_runs = 1;           // runs at once, each on one thread
};

struct ExplorationBenchmarkRun {
  unsigned world_seed = 0;
  int run_seed = 0;
  std::string world_kind;
  ExplorationReport report;
  std::string error;  // "" unless the run failed; then the report is empty
};

// Runs every world seed x run seed: generates the world into
// <dir>/world_<w>.ini (+ .truth.yaml/.pgm), explores it with `config` (the stereo engine on one
// thread) into <dir>/world_<w>_seed_<s>.* (exploration_run.h), and writes, each atomically:
//   <dir>/runs.csv, runs.json  one row / object per run: coverage, seen, time to 80/90/95%
//                              coverage, distance, collisions and what was hit, stop reason,
//                              simulated and wall time
//   <dir>/summary.md           the table and its summary: mean, worst, median time to 90%
//   <dir>/montage.png          every run's map with its path, labelled
// `on_run` is called after each run (runs done, runs in all). A run that throws is reported with
// its error; the others go on.
std::vector<ExplorationBenchmarkRun> runExplorationBenchmark(
    ExplorationConfig config, const ExplorationBenchmarkJob& job,
    const std::function<void(size_t done, size_t total)>& on_run = {});

// The summary lines of summary.md: "mean coverage 93.1% (worst 71.0%, world 7 seed 1), ...".
std::string benchmarkSummary(const std::vector<ExplorationBenchmarkRun>& runs);

}  // namespace stereonav
