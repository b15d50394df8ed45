#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "closed_loop/path_scan_accuracy.h"
#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "mapping/rawlog_mapping.h"
#include "report/coverage_timeline.h"
#include "report/summary_page.h"
#include "simulator/simulation_recorder.h"
#include "simulator/world_loader.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav report --config C.ini --world W.ini --explore PREFIX --rawlog R.rawlog --out DIR\n"
    "                        [--panels N] [--scan-truth-every N]\n"
    "Makes a page of an exploration run by 'stereonav explore --config C.ini --world W.ini --out PREFIX\n"
    "--record R.rawlog': replays R.rawlog through the same mapping pipeline to measure the coverage of\n"
    "the reachable free floor as the map grew, and writes DIR/index.html (the map with the path, the\n"
    "explorer's last plan, the coverage curve, N debug panels spread over the run; default 4),\n"
    "DIR/coverage.csv ('t,coverage,seen_coverage', one line per simulated second), DIR/panels/ and\n"
    "the replayed map DIR/map.{png,yaml,pgm,gridmap,3Dscene,stats.json}. Every N-th frame (default 5;\n"
    "0: none) is also rendered again at its true pose and its stereo scan compared with the scan of the\n"
    "renderer's exact disparity: the share of columns that agree, that read an obstacle nearer than\n"
    "anything there (within 2 m: what the guard brakes for) and that miss an obstacle within 2 m, on the\n"
    "page and in DIR/scan_accuracy.json.\n";

std::string percent(double fraction) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << 100.0 * fraction << "%";
  return text.str();
}

}  // namespace

int runReportCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string config_path = command_line.required("config");
  const std::string world_path = command_line.required("world");
  const std::string explore_prefix = command_line.required("explore");
  const std::string rawlog_path = command_line.required("rawlog");
  const std::string out = command_line.required("out");
  const int panels = command_line.intValue("panels", 0, 100).value_or(4);
  const int scan_truth_every = command_line.intValue("scan-truth-every", 0, 1000000).value_or(5);
  command_line.rejectUnknown();
  if (panels < 0) throw UsageError("--panels: must not be negative");

  namespace fs = std::filesystem;
  const ExplorationConfig config = loadExplorationConfig(config_path);
  const World world = loadWorld(world_path);
  const size_t frames = loadPoseList(SimulationRecorder::groundTruthPath(rawlog_path)).size();
  fs::create_directories(fs::path(out) / "panels");
  for (const char* image : {".path.png", ".plan.png"}) {
    if (!fs::exists(explore_prefix + image)) throw std::runtime_error(explore_prefix + image + ": missing");
  }

  CoverageTimelineJob job;
  job.rawlog_path = rawlog_path;
  job.output_prefix = out + "/map";
  if (panels > 0) {
    job.debug_panel_directory = out + "/panels";
    job.debug_panel_every = std::max<size_t>(1, (frames + panels - 1) / static_cast<size_t>(panels));
  }
  std::cerr << "stereonav report: replaying " << frames << " frames of " << rawlog_path << "\n";
  const std::vector<CoverageSample> coverage = replayCoverage(config, world, job);
  writeStringAtomically(out + "/coverage.csv", coverageCsv(coverage));
  std::optional<ScanAccuracy> scan_accuracy;
  if (scan_truth_every > 0) {
    std::cerr << "stereonav report: rendering one frame in " << scan_truth_every
              << " again to compare its stereo scan with the truth\n";
    scan_accuracy = scanAccuracyAlongPath(config, world, loadPoseList(SimulationRecorder::groundTruthPath(rawlog_path)),
                                          static_cast<size_t>(scan_truth_every), ScanAccuracyOptions{});
    writeStringAtomically(out + "/scan_accuracy.json", scan_accuracy->toJson() + "\n");
    std::cerr << "stereonav report: stereo scans against the truth: " << scan_accuracy->toText() << "\n";
  }
  fs::copy_file(explore_prefix + ".path.png", out + "/path.png", fs::copy_options::overwrite_existing);
  fs::copy_file(explore_prefix + ".plan.png", out + "/plan.png", fs::copy_options::overwrite_existing);

  SummaryPage page;
  page.title = "stereonav explore: " + fs::path(world_path).filename().string();
  page.facts = {{"world", world_path},
                {"configuration", config_path},
                {"frames", std::to_string(frames)},
                {"coverage at the end (reachable free floor mapped free)", percent(coverage.back().coverage)},
                {"seen at the end (mapped at all)", percent(coverage.back().seen_coverage)},
                {"run statistics", explore_prefix + ".stats.json"}};
  if (scan_accuracy) page.facts.emplace_back("stereo scans against the truth", scan_accuracy->toText());
  page.images = {{"the map with the robot's path (green start, blue end)", "path.png"},
                 {"the explorer's last plan", "plan.png"}};
  page.coverage = coverage;
  for (size_t frame = 0; panels > 0 && frame < frames; frame += job.debug_panel_every) {
    char file[32];
    std::snprintf(file, sizeof file, "panel_%06zu.png", frame);  // as saveDebugPanel names them
    std::ostringstream caption;
    caption << "frame " << frame << ", t = " << static_cast<double>(frame) / config.simulator.simulation.frame_rate_hz
            << " s";
    page.panels.emplace_back(caption.str(), std::string("panels/") + file);
  }
  writeStringAtomically(out + "/index.html", summaryHtml(page));
  std::cerr << "stereonav report: coverage " << percent(coverage.back().coverage) << " (seen "
            << percent(coverage.back().seen_coverage) << ") after " << coverage.back().time_s
            << " s; wrote " << out << "/index.html\n";
  return 0;
}

}  // namespace stereonav::app
