#pragma once

#include <optional>

namespace stereonav {

// What the heading filter must know of odometry's last turn beyond its noise model: the doubt of
// FloorOdometry's wheel steps, which its noise model of the floor's steps does not cover.
struct TurnDoubt {
  double sigma_rad = 0.0;  // one sigma of the wheels' random error in this turn, radians
  // One sigma of the error from the wheels' turn scale, while the floor has not yet measured it.
  double scale_sigma_rad = 0.0;
  // Set on the step the scale becomes known: the earlier doubtful turns were off by this factor,
  // and this step's turn already includes their correction (odometry's pose is right at once).
  // Fixing those turns where they were taken, rather than as one late turn, keeps the wall
  // directions first seen during them right too.
  std::optional<double> earlier_turns_scale;
};

}  // namespace stereonav
