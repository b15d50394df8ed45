#pragma once

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace stereonav {

// One pose of a trajectory and when it was taken (seconds).
struct StampedPose {
  double time_s = 0.0;
  mrpt::poses::CPose2D pose;
};

// The TUM RGB-D benchmark's trajectory text (what evo and the TUM tools read): per line
// "timestamp tx ty tz qx qy qz qw", the planar pose at z = 0 turned about z.
std::string toTumText(const std::vector<StampedPose>& trajectory);

// Writes toTumText atomically; throws std::runtime_error naming `path` on failure.
void saveTumTrajectory(const std::string& path, const std::vector<StampedPose>& trajectory);

// Reads a trajectory in either text format, told apart per line by its field count:
//   TUM, 8 fields "t x y z qx qy qz qw" (the heading is the quaternion's turn about z);
//   the simulator's pose list, 4 fields "t x y phi" (stereonav simulate's OUT.gt.txt).
// '#' starts a comment. Throws std::runtime_error naming the file and line on anything else.
std::vector<StampedPose> loadTrajectory(const std::string& path);

}  // namespace stereonav
