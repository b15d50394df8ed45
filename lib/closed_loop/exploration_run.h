#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "closed_loop/exploration_config.h"
#include "closed_loop/exploration_report.h"
#include "simulator/world.h"

namespace stereonav {

struct ExplorationJob {
  // Writes the map outputs of `stereonav map` (<prefix>.gridmap .png .yaml .pgm .3Dscene), the
  // navigation trace (navigation_trace.h: .path.txt .truth.txt .navlog.csv .reactivenavlog), and
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
  // Simulated seconds between measurements of the coverage while the run goes on, for
  // ExplorationReport::time_to_coverage_s (and the end is always measured).
  double coverage_sample_period_s = 5.0;
};

// Called from the loop: after each frame is mapped (frames so far, the total the time limit
// allows), and asked whether to stop early (the outputs are written as at the time limit).
struct ExplorationCallbacks {
  std::function<void(size_t frames, size_t frame_limit)> on_frame;
  std::function<bool()> stop_requested;
};

// The closed loop (paper section 5): the simulation (simulator/simulation.h) renders a frame,
// the mapping pipeline adds it to the map, the explorer plans on the new map; between frames the
// explorer commands the simulated robot through MRPT's navigator interface every control period.
ExplorationReport runExploration(const World& world, const ExplorationConfig& config, const ExplorationJob& job,
                                 const ExplorationCallbacks& callbacks = {});

}  // namespace stereonav
