#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "evaluation/trajectory_error.h"
#include "mapping/mapping_options.h"
#include "progress_meter.h"
#include "mapping/rawlog_mapping.h"
#include "sigint_stop.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav map --config FILE.ini --rawlog IN.rawlog --out PREFIX\n"
    "                     [--poses odometry|localized|ground_truth]\n"
    "                     [--use-ground-truth-poses GT.txt]\n"
    "                     [--debug-panels DIR] [--virtual-scans OUT.rawlog]\n"
    "Replays a recorded run through the stereo mapping pipeline (sections [rig] [rawlog] [stereo]\n"
    "[spike_removal] [projection] [grid] [mapping] [localization] of FILE.ini) and writes\n"
    "PREFIX.gridmap (MRPT COccupancyGridMap2D), PREFIX.png, PREFIX.yaml + PREFIX.pgm (ROS),\n"
    "PREFIX.3Dscene (map and path, for SceneViewer3D), PREFIX.traj.tum (the pose of every frame,\n"
    "TUM format) and PREFIX.stats.json; optionally one debug panel PNG per frame in DIR, and a\n"
    "rawlog of virtual laser scans with odometry for icp-slam (ini/icp_slam_virtual_scans.ini).\n"
    "Robot poses (--poses, default odometry; ground_truth when only GT.txt is given):\n"
    "  odometry      the rawlog's odometry (dead reckoning)\n"
    "  localized     odometry corrected by matching each frame's stereo scan against the map so far\n"
    "  ground_truth  GT.txt: 't x y phi' (as 'stereonav simulate' writes) or TUM, one per frame\n"
    "With GT.txt and odometry or localized poses, the trajectory error against GT.txt is printed.\n"
    "A damaged rawlog is mapped up to the damage; Ctrl-C stops after the current frame. Both\n"
    "still write every output.\n"
    "Exit status: 0 the whole rawlog was mapped; 3 partial map (damaged rawlog or Ctrl-C),\n"
    "outputs written; 1 no frame could be mapped (outputs hold an empty map) or any other\n"
    "error; 2 usage error.\n";

struct MapRequest {
  std::string config_path;
  MappingJob job;
  std::optional<std::string> truth_path;
};

MapRequest parseMapRequest(CommandLine& command_line) {
  MapRequest request;
  MappingJob& job = request.job;
  request.config_path = command_line.required("config");
  job.rawlog_path = command_line.required("rawlog");
  job.output_prefix = command_line.required("out");
  job.debug_panel_directory = command_line.value("debug-panels").value_or("");
  job.virtual_scan_rawlog = command_line.value("virtual-scans").value_or("");
  request.truth_path = command_line.value("use-ground-truth-poses");
  const std::optional<std::string> pose_source = command_line.value("poses");
  command_line.rejectUnknown();
  job.pose_source = pose_source ? parsePosesOption(*pose_source)
                                : (request.truth_path ? MapPoseSource::kGroundTruth : MapPoseSource::kOdometry);
  if (job.pose_source == MapPoseSource::kGroundTruth && !request.truth_path) {
    throw UsageError("--poses ground_truth needs --use-ground-truth-poses GT.txt");
  }
  checkFileName(job.output_prefix, "--out");
  checkWritableFolder(folderOf(job.output_prefix), "--out");
  if (!job.debug_panel_directory.empty()) checkWritableFolder(job.debug_panel_directory, "--debug-panels");
  if (!job.virtual_scan_rawlog.empty()) {
    checkFileName(job.virtual_scan_rawlog, "--virtual-scans");
    checkWritableFolder(folderOf(job.virtual_scan_rawlog), "--virtual-scans");
  }
  return request;
}

// Progress on a terminal, Ctrl-C or SIGTERM ends the map with what was mapped so far.
MappingReport mapWithProgress(const MappingOptions& options, const MappingJob& job) {
  std::optional<ProgressMeter> progress;
  if (isatty(STDERR_FILENO) != 0) progress.emplace(std::cerr, "mapping", countRawlogFrames(job.rawlog_path, options));
  SigintStopRequest sigint;
  MappingCallbacks callbacks;
  callbacks.on_frame = [&](size_t frames, const mrpt::maps::CMetricMap&) {
    if (progress) progress->update(frames);
  };
  callbacks.stop_requested = [&] { return sigint.requested(); };
  MappingReport report = mapRawlog(options, job, callbacks);
  if (progress) progress->finish(report.frames_mapped);
  return report;
}

}  // namespace

int runMapCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  MapRequest request = parseMapRequest(command_line);
  const MappingJob& job = request.job;
  const MappingOptions options = loadMappingOptionsFile(request.config_path);
  if (request.truth_path) request.job.ground_truth_poses = loadPoseList(*request.truth_path);

  const MappingReport report = mapWithProgress(options, job);
  for (const std::string& warning : report.calibration_warnings) {
    std::cerr << "stereonav map: calibration: " << warning << "\n";
  }
  if (report.frames_mapped == 0) {
    // A failure: one line saying why (the outputs, written anyway, hold an empty map).
    std::string why = report.damage ? report.damage->describe(job.rawlog_path) : report.skipped.summary();
    if (why.empty()) why = "no stereo frame in it";
    // Both files are named: the rawlog's frames may be fine for another configuration's [rig].
    std::cerr << "stereonav map: no frame of " << job.rawlog_path << " could be mapped with "
              << request.config_path << ": " << why << "\n";
    return 1;
  }
  std::cerr << "stereonav map: " << report.summary() << "\n"
            << "stereonav map: wrote " << job.output_prefix
            << ".{gridmap,png,yaml,pgm,3Dscene,traj.tum,stats.json}"
            << (job.virtual_scan_rawlog.empty() ? "" : " and " + job.virtual_scan_rawlog) << "\n";
  if (request.truth_path && job.pose_source != MapPoseSource::kGroundTruth) {
    std::vector<mrpt::poses::CPose2D> truth = job.ground_truth_poses;
    truth.resize(std::min(truth.size(), report.path.size()));
    std::cerr << "stereonav map: trajectory error against " << *request.truth_path << ":\n"
              << trajectoryError(report.path, truth).toText();
  }
  return report.complete() ? 0 : kPartialWorkStatus;
}

MapPoseSource parsePosesOption(const std::string& text) {
  try {
    return parseMapPoseSource(text);
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--poses: ") + error.what());
  }
}

}  // namespace stereonav::app
