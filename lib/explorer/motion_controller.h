#pragma once

#include <mrpt/poses/CPose2D.h>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

#include "explorer/explorer_options.h"
#include "explorer/navigation_grid.h"
#include "explorer/velocity_command.h"

namespace stereonav {

// How the robot moves towards what the phase machine chose: along a planned path (a carrot
// lookahead_m ahead), turning on the spot to face a point, a full look-around, approaching an
// escape cell, and reversing out of a blocked spot. Owns the look-around's progress and where the
// last one was; everything else is a function of the pose and the plan.
class MotionController {
 public:
  explicit MotionController(const ExplorerOptions& options);

  // Turning on the spot towards (x, y), as fast as the turn can still be braked to a stop at the
  // heading (turn_braking), never slower than min_turn_rate.
  VelocityCommand turnTowards(const mrpt::poses::CPose2D& pose, double x, double y) const;
  // Whether the robot heads within facing_tolerance_rad of (x, y).
  bool faces(const mrpt::poses::CPose2D& pose, double x, double y) const;

  struct Drive {
    VelocityCommand command;
    bool driving = false;  // false: turning on the spot to face the path first
    double path_length_m = 0.0;
  };
  // Following `path` (grid cells, the robot's first): a robot not yet driving first faces the
  // carrot; one driving turns on the spot again past turn_in_place_rad. Slower near obstacles,
  // with the heading error, and braking in time for the path's end (the edge of the known map).
  Drive drive(const mrpt::poses::CPose2D& pose, const std::vector<cv::Point>& path, const NavigationGrid& grid,
              bool driving) const;

  // A full turn on the spot at look_around_turn_rate. `continuing`: the previous cycle's command
  // was this look-around's; else it starts again. Empty once the turn is complete.
  std::optional<VelocityCommand> lookAround(const mrpt::poses::CPose2D& pose, bool continuing);
  // True from a complete look-around until the robot moves look_around_spacing_m from it
  // (forgetLookAroundIfMoved).
  bool lookedAroundHere() const { return looked_around_here_; }
  void forgetLookAroundIfMoved(const mrpt::poses::CPose2D& pose);
  void forgetLookAround() { looked_around_here_ = false; }

  // Towards a nearby point at escape_speed_mps, after facing it.
  VelocityCommand approach(const mrpt::poses::CPose2D& pose, const cv::Point2d& point) const;

  // Reversing out of a blocked spot: the cameras do not see behind, so only where the map has
  // room for the body all along the way back (back_off_speed_mps for back_off_s).
  bool roomBehind(const mrpt::poses::CPose2D& pose, const NavigationGrid& grid) const;
  VelocityCommand reverse() const { return {-options_.back_off_speed_mps, 0.0}; }
  // Hemmed in behind as well: turning on the spot (a disc turning touches nothing) shows the
  // cameras another way out.
  VelocityCommand turnOnTheSpot() const { return {0.0, options_.look_around_turn_rate}; }

 private:
  double headingError(const mrpt::poses::CPose2D& pose, double x, double y) const;

  ExplorerOptions options_;
  double turned_rad_ = 0.0;  // by the current look-around
  // The heading at the previous look-around cycle; none before the first, so that a look-around
  // the explorer starts in (initial_look_around) does not count the start heading as turned.
  std::optional<double> last_phi_;
  bool looked_around_here_ = false;
  double look_around_x_ = 0.0;
  double look_around_y_ = 0.0;
};

}  // namespace stereonav
