#pragma once

#include <vector>

#include <Eigen/Core>

#include "localization/wall_heading_filter.h"
#include "localization/wall_segments.h"

namespace stereonav {

// How WallPositionFilter keeps the position by the walls' offsets (keys of [localization]).
struct WallPositionOptions {
  // Off: the position is odometry's, driven along the filtered heading.
  bool enabled = true;
  // The position noise per metre driven (one sigma, along and across) that odometry adds beyond
  // what its distance scale and the heading's error explain (both are in the state). With 0.03
  // the position errors on four recorded office runs were 1.0-3.7 times the filter's variance
  // (NEES per axis pair, where 1 is consistent), and the errors least.
  double position_noise_per_m = 0.03;
  // How far odometry's distances may be off in scale (a wheel radius off its nominal length): one
  // sigma of the prior on the scale that the filter learns.
  double distance_scale_sigma = 0.05;
  // A segment's offset is never trusted to better than this: its readings' range errors are not
  // independent (a disparity bias moves the whole stretch).
  double min_offset_sigma_m = 0.02;
  // A segment continues a known wall only where it comes within this of the stretch of that wall
  // seen so far, along the line: two rooms' walls on one line are often one wall with a door in
  // it, but a wall much farther on may be another one slightly off the line.
  double max_join_gap_m = 1.0;
};

// Keeps the robot's position from drifting by the walls it sees again: each straight stretch of
// wall along a known wall direction (WallHeadingFilter) says how far the robot is from that wall,
// whatever its heading, and a wall seen again after a loop tells odometry's drift since.
//
// A Kalman filter whose state is the position, odometry's distance scale, and the offset from
// the origin of each wall line seen (SLAM with wall lines as landmarks). With the wall's normal
// taken from the known directions, a segment's offset measures `wall offset - normal . position`:
// the filter is linear but for the scale. A wall line is known by the side it was seen from
// (the two faces of a thin wall are two lines), its offset (within the gate of gate_sigmas of
// WallHeadingOptions) and the stretch of it seen so far.
//
// The state also holds the heading's error: driving on a heading that is off moves the position
// sideways by the distance times the error, the same error frame after frame until the walls'
// directions correct the heading. So a heading correction tells the position too: driven 5 m on
// a heading 2 degrees off, the robot is 17 cm to the side of where it thought.
class WallPositionFilter {
 public:
  WallPositionFilter(const WallPositionOptions& options, const WallHeadingOptions& heading_options,
                     const Eigen::Vector2d& start);

  // The position after a frame: odometry measured `displacement` (in the frame of the previous
  // pose, which headed `previous_heading`); WallHeadingFilter predicted the heading `predicted`
  // (its prediction()) and corrected it to `heading` (its estimate()); the robot sees `segments`
  // (robot frame). `directions`: the wall directions known, WallHeadingFilter::directions().
  Eigen::Vector2d update(const Eigen::Vector2d& displacement, double previous_heading,
                         const HeadingEstimate& predicted, const HeadingEstimate& heading,
                         const std::vector<double>& directions, const std::vector<WallSegment>& segments);

  Eigen::Vector2d position() const { return state_.head<2>(); }
  Eigen::Matrix2d positionCovariance() const { return covariance_.topLeftCorner<2, 2>(); }
  double distanceScale() const { return state_(2); }
  size_t wallCount() const { return walls_.size(); }
  // How many of the last frame's segments corrected the position.
  int lastFrameCorrections() const { return frame_corrections_; }

 private:
  struct WallLine {
    double normal_rad = 0.0;  // world direction from the wall toward the side it was seen from
    // The stretch seen so far, along the line's direction (normal + 90 degrees) from the origin.
    double along_min = 0.0;
    double along_max = 0.0;
  };

  // A segment's offset against a wall line's, as the filter predicts it.
  struct Innovation {
    double value = 0.0;             // measured minus predicted
    Eigen::RowVectorXd h_covariance;  // the measurement row times the covariance
    double variance = 0.0;
  };

  void predict(const Eigen::Vector2d& displacement, double previous_heading);
  // The heading filter moved the heading by `shift` and left its variance at `variance`.
  void followHeading(double shift, double variance);
  Innovation innovation(size_t wall, double offset_m, double variance) const;
  // The wall the segment (world normal, offset, stretch along) continues, or walls_.size().
  size_t associate(double normal_rad, double offset_m, double variance, double along_min,
                   double along_max) const;
  void correct(const Innovation& innovation);
  void addWall(double normal_rad, double offset_m, double variance, double along_min, double along_max);
  // Turns a wall line about the middle of its seen stretch to the refined direction `normal_rad`.
  void turnWall(size_t wall, double normal_rad);

  WallPositionOptions options_;
  double gate_sigmas_;
  double max_direction_rad_;
  // Position x, y; distance scale; the heading's error; each wall line's offset.
  Eigen::VectorXd state_;
  Eigen::MatrixXd covariance_;
  std::vector<WallLine> walls_;
  int frame_corrections_ = 0;
};

}  // namespace stereonav
