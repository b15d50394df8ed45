#include <iostream>
#include <sstream>
#include <stdexcept>

#include "command_line.h"
#include "commands.h"
#include "common/ini_section.h"
#include "evaluation/map_score.h"
#include "occupancy_grid/ros_map.h"
#include "evaluation/score_overlay.h"
#include "evaluation/trajectory_error.h"
#include "mapping/rawlog_mapping.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav score --map MAP.yaml --truth GT.yaml [--poses GT.txt] [--start X,Y]\n"
    "                       [--tolerance CELLS] [--fov-deg DEG] [--view-range M] [--json]\n"
    "                       [--overlay OUT.png]\n"
    "Scores an occupancy map against a ground-truth map, both ROS map_server YAML (any origin,\n"
    "extent, resolution; a cell is occupied/free by its YAML's thresholds), over the ground\n"
    "truth's known cells, reading the map at each cell's centre:\n"
    "  occupied precision  map-occupied cells with a true obstacle within CELLS (default 1)\n"
    "  occupied recall     true obstacle cells with a map-occupied cell within CELLS\n"
    "  false free          true obstacle cells the map calls free (the dangerous error)\n"
    "  coverage            share of the reachable true free space the map calls free\n"
    "With --poses (the run's true poses, 't x y phi' per frame as 'stereonav simulate' writes)\n"
    "recall and false free count only obstacles in view: hit first by rays over --fov-deg\n"
    "(default 90) up to --view-range metres (default 5) from some pose; reachable free space is\n"
    "the free cells 4-connected to --start, else to the first pose; with neither, all free cells.\n"
    "--overlay draws what was counted: map-occupied green (correct) / red (wrong), true obstacles\n"
    "black (found) / blue (missed) / dark grey (not counted), magenta false free, light green\n"
    "free space the map calls free.\n"
    "\n"
    "usage: stereonav score --traj EST --traj-truth GT [--json]\n"
    "Absolute trajectory error of EST against GT, each 't x y phi' or TUM 't x y z qx qy qz qw'\n"
    "per line with one pose per frame (e.g. 'stereonav map' PREFIX.traj.tum against the run's\n"
    "OUT.gt.txt): EST is moved rigidly onto GT's first pose, then the position error's RMS, max and\n"
    "final value (drift) and the heading error are reported.\n";

int runTrajectoryScore(CommandLine& command_line) {
  const std::string estimate_path = command_line.required("traj");
  const std::string truth_path = command_line.required("traj-truth");
  const bool json = command_line.flag("json");
  command_line.rejectUnknown();
  const std::vector<mrpt::poses::CPose2D> estimate = loadPoseList(estimate_path);
  const std::vector<mrpt::poses::CPose2D> truth = loadPoseList(truth_path);
  if (estimate.size() != truth.size()) {
    throw std::runtime_error(estimate_path + " has " + std::to_string(estimate.size()) +
                             " poses, " + truth_path + " " + std::to_string(truth.size()) +
                             ": they must pair one to one");
  }
  const TrajectoryError error = trajectoryError(estimate, truth);
  std::cout << (json ? error.toJson() : error.toText());
  return 0;
}

std::pair<double, double> parsePoint(const std::string& text) {
  double x = 0, y = 0;
  const size_t comma = text.find(',');
  if (comma == std::string::npos || !parseFiniteDouble(text.substr(0, comma), x) ||
      !parseFiniteDouble(text.substr(comma + 1), y)) {
    throw UsageError("--start: expected X,Y in metres, got '" + text + "'");
  }
  return {x, y};
}

}  // namespace

int runScoreCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help", "json"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  if (command_line.value("traj")) return runTrajectoryScore(command_line);
  const std::string map_path = command_line.required("map");
  const std::string truth_path = command_line.required("truth");
  const std::optional<std::string> poses_path = command_line.value("poses");
  const std::optional<std::string> start = command_line.value("start");
  MapScoreOptions options;
  // Bounds keep the work in proportion to the maps: the tolerance window and the rays cast
  // from every pose grow with them.
  options.tolerance_cells = command_line.intValue("tolerance", 0, 100).value_or(options.tolerance_cells);
  options.view_fov_deg = command_line.doubleValue("fov-deg", 1e-3, 360.0).value_or(options.view_fov_deg);
  options.view_range_m = command_line.doubleValue("view-range", 1e-3, 100.0).value_or(options.view_range_m);
  const bool json = command_line.flag("json");
  const std::optional<std::string> overlay_path = command_line.value("overlay");
  command_line.rejectUnknown();
  if (start) options.start = parsePoint(*start);

  const RosMap map = loadRosMap(map_path);
  const RosMap truth = loadRosMap(truth_path);
  if (poses_path) options.poses = loadPoseList(*poses_path);
  const MapScore score = scoreMap(map, truth, options);
  if (overlay_path) saveScoreOverlay(map, truth, options, *overlay_path);
  std::cout << (json ? score.toJson() : score.toText());
  return 0;
}

}  // namespace stereonav::app
