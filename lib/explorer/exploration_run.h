#pragma once

#include <optional>
#include <string>
#include <vector>

#include "explorer/exploration_coverage.h"
#include "explorer/explorer_options.h"
#include "explorer/simulated_robot_interface.h"
#include "mapping/mapping_options.h"
#include "simulator/simulator_config.h"
#include "simulator/world.h"

namespace stereonav {

// Everything a closed-loop exploration run is configured with, from one ini file: the
// simulator's sections ([rig] [sim_sensor] [sim_robot] [simulation] [rawlog] [ground_truth_map],
// as `stereonav simulate` reads them), the mapping pipeline's (as `stereonav map` reads them,
// so a recorded run replays to the same map) and [explorer]. Unknown keys are rejected.
struct ExplorationConfig {
  // Of [simulation], frame_rate_hz, control_rate_hz and max_duration_s are used.
  SimulatorConfig simulator;
  MappingOptions mapping;
  ExplorerOptions explorer;
  // [explorer] pose_source = odometry | ground_truth (simulated_robot_interface.h).
  PoseSource pose_source = PoseSource::kOdometry;
};

// Throws ConfigError naming the file, section and key.
ExplorationConfig loadExplorationConfig(const std::string& path);

struct ExplorationJob {
  // Writes the map outputs of `stereonav map` (<prefix>.gridmap .png .yaml .pgm .3Dscene), and
  // <prefix>.path.txt   the pose the map was built at, per frame "t x y phi" (pose_source)
  // <prefix>.truth.txt  true pose per frame "t x y phi"
  // <prefix>.navlog.csv the navigation trace, one line per frame
  // <prefix>.reactivenavlog the same for MRPT's navlog-viewer (reactive_nav_log.h)
  // <prefix>.path.png   the map with the path drawn (red; start green, end blue)
  // <prefix>.plan.png   the explorer's last plan (FrontierExplorer::planImage)
  // <prefix>.stats.json ExplorationReport::toJson()
  std::string output_prefix;
  // "" = do not record; else the rig frames with odometry (+ .gt.txt); with pose_source =
  // ground_truth, `stereonav map --use-ground-truth-poses OUT.gt.txt` replays it to the same map.
  std::string record_rawlog;
  std::optional<double> max_time_s;  // default: [simulation] max_duration_s
  // Seeds the camera noise and odometry errors, and moves the start up to 0.5 m from the world's
  // start pose with any heading (on free floor); without it, the ini's seeds and start pose.
  std::optional<int> seed;
};

// A contact the simulator counted: when, where (true pose) and with what.
struct CollisionEvent {
  double time_s = 0.0;
  double x = 0.0;
  double y = 0.0;
  double speed_mps = 0.0;  // the robot's speed just before
  std::string with;        // a moving obstacle's section name, or "static"
};

struct ExplorationReport {
  ExplorationCoverage coverage;
  double start_x = 0.0;
  double start_y = 0.0;
  double start_phi = 0.0;
  double distance_m = 0.0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  double top_speed_mps = 0.0;
  double frame_rate_hz = 0.0;
  double pipeline_ms_per_frame = 0.0;  // the mapping pipeline alone
  size_t frames = 0;
  int collisions = 0;           // contacts the simulator counted (robot_options' footprint)
  std::vector<CollisionEvent> collision_events;
  int blocked_reversals = 0;    // times the explorer found itself blocked and reversed
  std::string stop_reason;

  std::string summary() const;
  std::string toJson() const;
};

ExplorationReport runExploration(const World& world, const ExplorationConfig& config, const ExplorationJob& job);

}  // namespace stereonav
