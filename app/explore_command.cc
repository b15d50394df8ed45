#include <unistd.h>

#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "progress_meter.h"
#include "sigint_stop.h"
#include "closed_loop/exploration_run.h"
#include "simulator/simulation_recorder.h"
#include "simulator/world_loader.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav explore --config C.ini --world W.ini --out PREFIX [--record OUT.rawlog]\n"
    "                         [--max-time S] [--seed N] [--poses odometry|localized|ground_truth]\n"
    "Explores the simulated world closed-loop (paper section 5): every frame the rig's images go\n"
    "through the stereo mapping pipeline, and the explorer drives the robot towards the nearest\n"
    "reachable frontier of the newest map until none is left. C.ini holds the simulator's sections\n"
    "([rig] [sim_sensor] [sim_robot] [simulation] [rawlog] [ground_truth_map]), the mapping\n"
    "pipeline's ([stereo] [spike_removal] [projection] [grid] [mapping]) and [explorer].\n"
    "Writes the map outputs of 'stereonav map' (PREFIX.gridmap .png .yaml .pgm .3Dscene), the path\n"
    "(PREFIX.path.txt odometry, PREFIX.truth.txt true poses, 't x y phi' per frame), the navigation\n"
    "trace PREFIX.navlog.csv (and PREFIX.reactivenavlog for MRPT's navlog-viewer), the map with the\n"
    "path PREFIX.path.png, the explorer's last plan PREFIX.plan.png and PREFIX.stats.json\n"
    "(coverage of the reachable free space against the world's ground truth: mapped free, and seen\n"
    "at all; distance, times, collisions and what they touched, stop reason). --record writes the\n"
    "frames with odometry as a rawlog (+ OUT.gt.txt) that 'stereonav map' replays to the same map.\n"
    "--seed N seeds the noise and moves the start up to 0.5 m with any heading; --max-time\n"
    "overrides [simulation] max_duration_s, --poses [explorer] pose_source. On a terminal a\n"
    "progress line shows frames, rate and ETA. Ctrl-C or SIGTERM ends the run early with every\n"
    "output written (exit status 3).\n";

}  // namespace

int runExploreCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string config_path = command_line.required("config");
  const std::string world_path = command_line.required("world");
  ExplorationJob job;
  job.output_prefix = command_line.required("out");
  job.record_rawlog = command_line.value("record").value_or("");
  job.max_time_s = command_line.doubleValue("max-time", 1e-3, 86400.0);
  job.seed = command_line.intValue("seed");
  const std::optional<std::string> poses = command_line.value("poses");
  command_line.rejectUnknown();
  if (job.max_time_s && !(*job.max_time_s > 0.0)) throw UsageError("--max-time: must be positive");
  checkFileName(job.output_prefix, "--out");
  checkWritableFolder(folderOf(job.output_prefix), "--out");

  ExplorationConfig config = loadExplorationConfig(config_path);
  if (poses) config.pose_source = parsePosesOption(*poses);
  if (!job.record_rawlog.empty()) SimulationRecorder::checkRecordable(config.simulator.rig, config_path);
  const World world = loadWorld(world_path);
  std::optional<ProgressMeter> progress;
  SigintStopRequest sigint;
  ExplorationCallbacks callbacks;
  callbacks.on_frame = [&](size_t frames, size_t frame_limit) {
    if (!progress && isatty(STDERR_FILENO) != 0) progress.emplace(std::cerr, "exploring", frame_limit);
    if (progress) progress->update(frames);
  };
  callbacks.stop_requested = [&] { return sigint.requested(); };
  const ExplorationReport report = runExploration(world, config, job, callbacks);
  if (progress) progress->finish(report.frames);
  std::cerr << "stereonav explore: " << report.summary() << "\n"
            << "stereonav explore: wrote " << job.output_prefix
            << ".{gridmap,png,yaml,pgm,3Dscene,path.txt,truth.txt,navlog.csv,reactivenavlog,path.png,plan.png,stats.json}"
            << (job.record_rawlog.empty() ? "" : " and " + job.record_rawlog) << "\n";
  return report.interrupted ? kPartialWorkStatus : 0;
}

}  // namespace stereonav::app
