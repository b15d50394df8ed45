#pragma once

#include <vector>

#include <Eigen/Core>

#include "localization/turn_doubt.h"
#include "localization/wall_segments.h"

namespace stereonav {

// The difference a - b of two directions of pairs of perpendicular lines, in [-pi/4, pi/4).
double perpendicularPairDifference(double a, double b);

// A heading and its variance.
struct HeadingEstimate {
  double heading = 0.0;
  double variance = 0.0;
};

// How WallHeadingFilter keeps the heading by the walls' directions (keys of [localization]).
struct WallHeadingOptions {
  WallSegmentOptions segments;
  // A segment's direction is never trusted to better than this: the fit's own sigma assumes
  // independent readings, and a stereo scan's are not.
  double min_sigma_deg = 0.5;
  // The heading noise odometry adds, as one sigma: per frame, per radian turned (in one frame),
  // per metre driven. Eight recorded 1200 s office runs drifted 1.5 degrees (RMS) per 2000
  // degrees turned once the turn scale was learned, as 0.01 per radian turned says; with 0.03 the
  // filter thought itself unsure (a gate wide enough for askew desks) after every look around.
  double heading_noise_deg_per_frame = 0.05;
  double heading_noise_per_rad = 0.01;
  double heading_noise_deg_per_m = 0.3;
  // How far odometry's turns may be off in scale (a wheel base off its nominal length): one
  // sigma of the prior on the scale that the filter learns.
  double turn_scale_sigma = 0.05;
  // A segment corrects the heading only within this many sigmas of a known wall direction...
  double gate_sigmas = 3.0;
  // ... and never when farther than this from every known direction.
  double max_correction_deg = 10.0;
  // A new pair of wall directions is taken up once this many segments, farther than
  // max_correction_deg from every known direction, agree on it within new_direction_spread_deg.
  int new_direction_segments = 8;
  double new_direction_spread_deg = 2.0;
  // One askew segment (a chair, a desk, a person) within the gate could pull the heading anywhere
  // within it. A segment that would turn the heading by more than new_direction_spread_deg, and
  // every segment while the heading is unsure (one sigma beyond it, after turning with no wall in
  // view), corrects it only once this many, in one frame or a few, agree within that spread.
  int agreeing_segments = 3;
};

// Keeps the robot's heading from drifting by the directions of the building's walls: walls run
// along few directions, most buildings at right angles, and once a direction is known every
// straight stretch of wall seen along it tells the heading again, with an error that does not grow
// with time as odometry's does.
//
// A Kalman filter whose state is the heading, odometry's turn scale (a wheel base off its nominal
// length turns every turn by the same factor) and the direction of each pair of perpendicular
// wall directions (SLAM with wall directions as landmarks): odometry's turn times the scale
// predicts the heading; each wall segment near a known direction corrects the heading, the scale
// and that direction together.
//
// A direction counts once several segments agree on it (one segment may be a chair set askew),
// and is then estimated from its first sighting on: the filter runs again over the frames so
// far, so the first direction is as sure as the heading was when it was first seen, and the
// map's frame stays that of the start.
class WallHeadingFilter {
 public:
  WallHeadingFilter(const WallHeadingOptions& options, double start_heading);

  // The heading after a frame: the robot turned `turn_rad` (as odometry, or a scan match, measured
  // it) and drove `driven_m` since the last one, and saw `segments` (robot frame).
  // `doubt`: the turn's doubt beyond the options' noise (FloorOdometry's wheel steps); when it
  // brings the scale of the earlier doubtful turns, the filter runs again with them corrected.
  double update(double turn_rad, double driven_m, std::vector<WallSegment> segments,
                const TurnDoubt& doubt = {});

  HeadingEstimate estimate() const { return {state_.heading, state_.covariance(0, 0)}; }
  // The last frame's heading before its segments corrected it: the one before, turned by odometry.
  const HeadingEstimate& prediction() const { return state_.prediction; }
  double turnScale() const { return state_.turn_scale; }
  // Each known pair of wall directions by its member in [-pi/4, pi/4) (the other is 90 degrees on).
  const std::vector<double>& directions() const { return state_.directions; }
  // How many of the last frame's segments corrected the heading.
  int lastFrameCorrections() const { return state_.frame_corrections; }

 private:
  // A segment that passed the gate while the heading was unsure, waiting for others to agree.
  struct HeldSegment {
    size_t direction = 0;
    double innovation = 0.0;
    double sigma = 0.0;
    double added_variance = 0.0;  // the heading's since the segment was seen
  };
  struct State {
    double heading = 0.0;
    HeadingEstimate prediction;
    double turn_scale = 1.0;
    std::vector<double> directions;
    Eigen::MatrixXd covariance;  // of (heading, turn scale, directions...)
    int frame_corrections = 0;
    std::vector<HeldSegment> held;
  };
  struct Frame {
    double turn_rad = 0.0;
    double driven_m = 0.0;
    std::vector<WallSegment> segments;
    double turn_sigma_rad = 0.0;
    double turn_scale_sigma_rad = 0.0;  // zeroed once the turn is corrected by the measured scale
  };
  struct Candidate {
    double direction = 0.0;
    double weight = 0.0;
    int segments = 0;
  };

  // Runs `frame` through `state`; segments far from every direction of `state` vote for new
  // directions when `vote` is set. Returns true when a vote confirms one.
  bool step(State& state, const Frame& frame, bool vote);
  // The variance of the innovation of a segment along `direction` with that sigma.
  static double innovationVariance(const State& state, size_t direction, double sigma);
  // The Kalman update of `state` by a segment along `direction` with that innovation.
  void correct(State& state, size_t direction, double innovation, double sigma) const;
  bool voteFor(double world_direction, double sigma);
  State startState(bool direction_confirmed) const;
  // The state after running every frame so far again, from the start.
  State rerun();

  WallHeadingOptions options_;
  double start_heading_;
  State state_;
  std::vector<Frame> frames_;  // every frame so far, to run again (a few segments each)
  std::vector<double> confirmed_;  // directions (mod 90 degrees) to take up at their first sighting
  std::vector<Candidate> candidates_;
};

}  // namespace stereonav
