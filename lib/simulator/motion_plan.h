#pragma once

#include <string>
#include <vector>

#include "simulator/number_list.h"

namespace stereonav {

// A velocity command that holds from `time_s` until the next command's time.
struct TimedCommand {
  double time_s = 0.0;
  double speed_mps = 0.0;
  double turn_rate = 0.0;  // rad/s, positive turns left
};

// How the simulated robot should move: either drive through waypoints in order, or play back
// velocity commands. Exactly one of the two lists is non-empty.
struct MotionPlan {
  std::vector<Point2> waypoints;
  // Sorted by time, starting at time 0; the run ends at the last command's time, so the last
  // command itself is never driven (write e.g. "20 0 0" to end after 20 s).
  std::vector<TimedCommand> commands;
};

// Reads a path file: one entry per line, either all "x y" (waypoints, metres in the world frame)
// or all "t v w" (seconds, m/s, rad/s). Blank lines and lines starting with '#' are skipped.
// Throws ConfigError naming the file and line for malformed, mixed, unsorted or empty files.
MotionPlan loadMotionPlan(const std::string& path);

// The same from text already read; `file_name` is only used in error messages.
MotionPlan parseMotionPlan(const std::string& text, const std::string& file_name);

}  // namespace stereonav
