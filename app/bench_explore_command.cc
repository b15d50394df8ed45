#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "closed_loop/exploration_benchmark.h"
#include "command_line.h"
#include "commands.h"
#include "progress_meter.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav bench-explore --config C.ini --out DIR [--worlds 1-20] [--seeds 1]\n"
    "                               [--max-time S] [--jobs N] [--poses odometry|localized|ground_truth]\n"
    "Explores generated worlds ('stereonav generate', seeds --worlds, e.g. 1-20 or 3,7,9) once per\n"
    "seed of --seeds, N runs at a time (default: one per core), each on one thread, with the\n"
    "ini C.ini of 'stereonav explore' (--poses overrides its [explorer] pose_source). Writes into\n"
    "DIR every world and run (as 'stereonav generate' and 'stereonav explore' do), runs.csv and\n"
    "runs.json (coverage, seen, time to 80/90/95% coverage, distance, collisions and what was hit,\n"
    "pose error, stop reason, simulated and wall time), summary.md (the table, mean, worst, median\n"
    "time to 90%) and montage.png (every map with its path). Fix the worlds and seeds of a\n"
    "comparison before tuning.\n";

// "1-20" or "3,7,9" (or both: "1-5,9").
std::vector<int> parseSeedList(const std::string& text, const std::string& option) {
  std::vector<int> seeds;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    try {
      const size_t dash = item.find('-', 1);
      const int first = std::stoi(item.substr(0, dash));
      const int last = dash == std::string::npos ? first : std::stoi(item.substr(dash + 1));
      if (first < 0 || last < first || last - first > 10000) throw std::invalid_argument(item);
      for (int seed = first; seed <= last; ++seed) seeds.push_back(seed);
    } catch (const std::exception&) {
      throw UsageError("--" + option + " '" + text + "': expected seeds like 1-20 or 3,7,9");
    }
  }
  if (seeds.empty()) throw UsageError("--" + option + ": no seeds");
  return seeds;
}

}  // namespace

int runBenchExploreCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string config_path = command_line.required("config");
  ExplorationBenchmarkJob job;
  job.output_directory = command_line.required("out");
  for (int seed : parseSeedList(command_line.value("worlds").value_or("1-20"), "worlds")) {
    job.world_seeds.push_back(static_cast<unsigned>(seed));
  }
  job.run_seeds = parseSeedList(command_line.value("seeds").value_or("1"), "seeds");
  job.max_time_s = command_line.doubleValue("max-time", 1e-3, 86400.0);
  job.parallel_runs = static_cast<size_t>(
      command_line.intValue("jobs", 1, 256).value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))));
  const std::optional<std::string> poses = command_line.value("poses");
  command_line.rejectUnknown();

  ExplorationConfig config = loadExplorationConfig(config_path);
  if (poses) config.pose_source = parsePosesOption(*poses);
  std::filesystem::create_directories(job.output_directory);
  std::optional<ProgressMeter> progress;
  const auto on_run = [&](size_t done, size_t total) {
    if (!progress && isatty(STDERR_FILENO) != 0) progress.emplace(std::cerr, "runs", total);
    if (progress) progress->update(done);
  };
  const std::vector<ExplorationBenchmarkRun> runs = runExplorationBenchmark(config, job, on_run);
  if (progress) progress->finish(runs.size());
  std::cerr << "stereonav bench-explore: " << benchmarkSummary(runs) << "\n"
            << "stereonav bench-explore: wrote " << job.output_directory
            << "/{runs.csv,runs.json,summary.md,montage.png} and every run's outputs\n";
  return 0;
}

}  // namespace stereonav::app
