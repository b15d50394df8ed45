#include "closed_loop/exploration_benchmark.h"

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

#include "closed_loop/exploration_run.h"
#include "common/atomic_file.h"
#include "common/csv_writer.h"
#include "common/image_file.h"
#include "common/json_writer.h"
#include "simulator/ground_truth_map.h"
#include "simulator/world_generator.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

std::string worldPrefix(const std::string& directory, unsigned world_seed) {
  return directory + "/world_" + std::to_string(world_seed);
}

std::string runPrefix(const std::string& directory, const ExplorationBenchmarkRun& run) {
  return worldPrefix(directory, run.world_seed) + "_seed_" + std::to_string(run.run_seed);
}

std::string milestoneName(size_t i) {
  return std::to_string(static_cast<int>(std::lround(100.0 * ExplorationReport::kCoverageMilestones[i])));
}

std::string collidedWith(const ExplorationReport& report) {
  std::string with;
  for (const CollisionEvent& event : report.collision_events) with += (with.empty() ? "" : " ") + event.with;
  return with;
}

std::string runsCsv(const std::vector<ExplorationBenchmarkRun>& runs) {
  std::vector<std::string> columns{"world", "kind", "seed", "coverage", "seen"};
  for (size_t i = 0; i < ExplorationReport::kCoverageMilestones.size(); ++i) {
    columns.push_back("time_to_" + milestoneName(i) + "_s");
  }
  for (const char* column : {"distance_m", "collisions", "collided_with", "pose_error_rms_m", "pose_error_max_m",
                             "stop_reason", "sim_time_s", "wall_time_s", "render_wall_s", "error"}) {
    columns.push_back(column);
  }
  CsvWriter csv(columns);
  for (const ExplorationBenchmarkRun& run : runs) {
    const ExplorationReport& report = run.report;
    csv.add(run.world_seed).add(run.world_kind).add(run.run_seed).add(report.coverage.coverage)
        .add(report.coverage.seen_coverage);
    for (const auto& time : report.time_to_coverage_s) csv.add(time.value_or(std::nan("")));
    csv.add(report.distance_m).add(report.collisions).add(collidedWith(report))
        .add(report.trajectory_error.rms_m).add(report.trajectory_error.max_m).add(report.stop_reason)
        .add(report.sim_time_s).add(report.wall_time_s).add(report.render_wall_s).add(run.error);
    csv.endRow();
  }
  return csv.str();
}

std::string runsJson(const std::vector<ExplorationBenchmarkRun>& runs) {
  std::string json = "[\n";
  for (size_t i = 0; i < runs.size(); ++i) {
    JsonWriter run;
    run.beginObject()
        .key("world").value(runs[i].world_seed)
        .key("kind").value(runs[i].world_kind)
        .key("seed").value(runs[i].run_seed)
        .key("error").value(runs[i].error)
        .key("report").json(runs[i].report.toJson())
        .endObject();
    json += run.str() + (i + 1 < runs.size() ? ",\n" : "\n");
  }
  return json + "]\n";
}

// The median of the times to 90% coverage, a run that never got there counting as never.
std::optional<double> medianTimeTo90(const std::vector<ExplorationBenchmarkRun>& runs) {
  std::vector<double> times;
  for (const ExplorationBenchmarkRun& run : runs) {
    times.push_back(run.report.time_to_coverage_s[1].value_or(std::numeric_limits<double>::infinity()));
  }
  if (times.empty()) return std::nullopt;
  std::sort(times.begin(), times.end());
  const double median = times.size() % 2 ? times[times.size() / 2]
                                         : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
  if (!std::isfinite(median)) return std::nullopt;
  return median;
}

std::string summaryMarkdown(const std::vector<ExplorationBenchmarkRun>& runs) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1);
  text << "| world | kind | seed | coverage | seen | to 80% | to 90% | to 95% | distance | collisions | stop | "
          "speed-up | without rendering |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const auto time = [](const std::optional<double>& t) {
    std::ostringstream cell;
    cell << std::fixed << std::setprecision(0);
    if (t) cell << *t << " s"; else cell << "-";
    return cell.str();
  };
  for (const ExplorationBenchmarkRun& run : runs) {
    const ExplorationReport& r = run.report;
    text << "| " << run.world_seed << " | " << run.world_kind << " | " << run.run_seed << " | "
         << 100.0 * r.coverage.coverage << "% | " << 100.0 * r.coverage.seen_coverage << "% | "
         << time(r.time_to_coverage_s[0]) << " | " << time(r.time_to_coverage_s[1]) << " | "
         << time(r.time_to_coverage_s[2]) << " | " << r.distance_m << " m | " << r.collisions
         << (r.collisions ? " (" + collidedWith(r) + ")" : "") << " | "
         << (run.error.empty() ? r.stop_reason : "error: " + run.error) << " | "
         << r.speedUp() << "x | " << r.speedUpWithoutRendering() << "x |\n";
  }
  text << "\n" << benchmarkSummary(runs) << "\n";
  return text.str();
}

// Every run's map with its path, scaled into equal tiles under a caption.
cv::Mat3b montage(const std::vector<ExplorationBenchmarkRun>& runs, const std::string& directory) {
  constexpr int kTile = 320, kCaption = 22;
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(runs.size())))));
  const int rows = static_cast<int>((runs.size() + columns - 1) / columns);
  cv::Mat3b sheet(std::max(1, rows) * (kTile + kCaption), columns * kTile, cv::Vec3b(255, 255, 255));
  for (size_t i = 0; i < runs.size(); ++i) {
    const cv::Rect cell(static_cast<int>(i % columns) * kTile, static_cast<int>(i / columns) * (kTile + kCaption),
                        kTile, kTile + kCaption);
    std::ostringstream caption;
    caption << "world " << runs[i].world_seed << " seed " << runs[i].run_seed << ": " << std::fixed
            << std::setprecision(1) << 100.0 * runs[i].report.coverage.coverage << "%, "
            << runs[i].report.collisions << " coll.";
    cv::putText(sheet, caption.str(), cell.tl() + cv::Point(4, 16), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    cv::Mat map;
    try {
      map = readImageFile(runPrefix(directory, runs[i]) + ".path.png", cv::IMREAD_COLOR);
    } catch (const std::exception&) {
      continue;  // a failed run has no map: its tile stays blank under its caption
    }
    const double scale = std::min(static_cast<double>(kTile) / map.cols, static_cast<double>(kTile) / map.rows);
    cv::Mat scaled;
    cv::resize(map, scaled, cv::Size(), scale, scale, scale < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
    scaled.copyTo(sheet(cv::Rect(cell.x, cell.y + kCaption, scaled.cols, scaled.rows)));
  }
  return sheet;
}

}  // namespace

std::string benchmarkSummary(const std::vector<ExplorationBenchmarkRun>& runs) {
  if (runs.empty()) return "no runs";
  double sum = 0.0, realtime = 0.0, without_rendering = 0.0;
  int collisions = 0;
  size_t below_85 = 0, failed = 0;
  const ExplorationBenchmarkRun* worst = &runs.front();
  for (const ExplorationBenchmarkRun& run : runs) {
    sum += run.report.coverage.coverage;
    collisions += run.report.collisions;
    below_85 += run.report.coverage.coverage < 0.85;
    failed += !run.error.empty();
    realtime += run.report.speedUp();
    without_rendering += run.report.speedUpWithoutRendering();
    if (run.report.coverage.coverage < worst->report.coverage.coverage) worst = &run;
  }
  const double n = static_cast<double>(runs.size());
  const std::optional<double> median90 = medianTimeTo90(runs);
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << runs.size() << " runs: mean coverage " << 100.0 * sum / n
       << "% (worst " << 100.0 * worst->report.coverage.coverage << "%, world " << worst->world_seed << " seed "
       << worst->run_seed << "), " << below_85 << " below 85%, " << collisions << " collision(s), median time to 90% "
       << (median90 ? std::to_string(static_cast<int>(std::lround(*median90))) + " s" : std::string("never"))
       << ", mean " << realtime / n << "x real time per run (" << without_rendering / n
       << "x without the simulator's rendering)" << (failed ? ", " + std::to_string(failed) + " failed" : "");
  return text.str();
}

std::vector<ExplorationBenchmarkRun> runExplorationBenchmark(ExplorationConfig config,
                                                             const ExplorationBenchmarkJob& job,
                                                             const std::function<void(size_t, size_t)>& on_run) {
  // Each run on one thread, OpenCV's parallel loops too (distance transforms, connected
  // components): otherwise they borrow the cores the other runs are on, and a run's speed-up is
  // not that of one core.
  config.mapping.stereo.threads = 1;
  const int opencv_threads = cv::getNumThreads();
  cv::setNumThreads(1);
  std::vector<ExplorationBenchmarkRun> runs;
  for (unsigned world_seed : job.world_seeds) {
    const GeneratedWorld world = generateWorld(world_seed);
    const std::string prefix = worldPrefix(job.output_directory, world_seed);
    writeStringAtomically(prefix + ".ini", world.ini_text);
    GroundTruthMap(loadWorld(prefix + ".ini"), config.simulator.ground_truth).writeRosMap(prefix + ".truth.yaml");
    for (int run_seed : job.run_seeds) runs.push_back({world_seed, run_seed, world.kind, {}, {}});
  }

  std::atomic<size_t> next{0}, done{0};
  std::mutex progress_mutex;
  const auto worker = [&] {
    for (size_t i = next++; i < runs.size(); i = next++) {
      ExplorationBenchmarkRun& run = runs[i];
      try {
        ExplorationJob exploration;
        exploration.output_prefix = runPrefix(job.output_directory, run);
        exploration.seed = run.run_seed;
        exploration.max_time_s = job.max_time_s;
        run.report = runExploration(loadWorld(worldPrefix(job.output_directory, run.world_seed) + ".ini"), config,
                                    exploration);
      } catch (const std::exception& e) {
        run.error = e.what();
      }
      const size_t finished = ++done;
      if (on_run) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        on_run(finished, runs.size());
      }
    }
  };
  std::vector<std::thread> threads;
  for (size_t t = 0; t < std::max<size_t>(1, std::min(job.parallel_runs, runs.size())); ++t) threads.emplace_back(worker);
  for (std::thread& thread : threads) thread.join();
  cv::setNumThreads(opencv_threads);

  const std::string& directory = job.output_directory;
  writeStringAtomically(directory + "/runs.csv", runsCsv(runs));
  writeStringAtomically(directory + "/runs.json", runsJson(runs));
  writeStringAtomically(directory + "/summary.md", summaryMarkdown(runs));
  writeImageFile(directory + "/montage.png", montage(runs, directory));
  return runs;
}

}  // namespace stereonav
