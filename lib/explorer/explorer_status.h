#pragma once

#include <cstddef>

namespace stereonav {

enum class ExplorerPhase {
  kLookingAround,      // a full turn on the spot (at the start, and before giving up)
  kTurning,            // facing the path before driving it (90 degree field of view)
  kDriving,            // following the cost-to-go towards the target frontier
  kLookingAtFrontier,  // arrived: facing the frontier so the cameras see past it
  kEscaping,           // the map closed in around the robot: back to the nearest traversable cell
  kBackingOff,         // told to drive but not moving (in contact with something unmapped): reverse
  kFinished,
};

const char* phaseName(ExplorerPhase phase);

// What the explorer is doing, for the navigation trace.
struct ExplorerStatus {
  ExplorerPhase phase = ExplorerPhase::kLookingAround;
  size_t frontiers = 0;            // frontier clusters in the newest map
  bool has_target = false;
  double target_x = 0.0;           // end of the current path (map frame)
  double target_y = 0.0;
  double cost_to_go = 0.0;         // metres-equivalent of path left (0 without target)
  double speed_command = 0.0;
  double turn_rate_command = 0.0;
  // How far the body could go along the command's arc before touching what the newest stereo
  // scans show (free_travel.h); the guard's look-ahead when nothing is in the way.
  double free_travel_m = 0.0;
};

}  // namespace stereonav
