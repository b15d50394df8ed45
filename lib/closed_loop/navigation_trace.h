#pragma once

#include <mrpt/poses/CPose2D.h>

#include <sstream>
#include <string>

#include "closed_loop/reactive_nav_log.h"
#include "closed_loop/simulated_robot_interface.h"
#include "common/csv_writer.h"
#include "explorer/frontier_explorer.h"
#include "simulator/simulation.h"

namespace stereonav {

// The record of a closed-loop run, one entry per frame:
//   <prefix>.path.txt       the pose the map was built at, "t x y phi"
//   <prefix>.truth.txt      the true pose, "t x y phi"
//   <prefix>.navlog.csv     the navigation trace (poses, speeds, the explorer's status)
//   <prefix>.reactivenavlog the same for MRPT's navlog-viewer (reactive_nav_log.h)
class NavigationTrace {
 public:
  NavigationTrace();

  // The frame just mapped at `map_pose`, with the robot as it is now and the explorer's status.
  void append(const SimulatedFrame& frame, const mrpt::poses::CPose2D& map_pose, const DifferentialDriveRobot& robot,
              CSimulatedRobotInterface& robot_interface, const ExplorerStatus& status, double robot_radius_m);

  // Writes the four files (atomically).
  void save(const std::string& prefix) const;

 private:
  std::ostringstream path_text_;
  std::ostringstream truth_text_;
  CsvWriter navlog_;
  ReactiveNavLog reactive_navlog_;
};

}  // namespace stereonav
