#include "localization/wall_heading_filter.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

// The difference of two directions of a pair of perpendicular lines, in [-pi/4, pi/4).
double pairAngleDifference(double a, double b) {
  double d = std::remainder(a - b, M_PI / 2);
  if (d >= M_PI / 4) d -= M_PI / 2;
  return d;
}

double pairDirection(double a) { return pairAngleDifference(a, 0.0); }

}  // namespace

WallHeadingFilter::WallHeadingFilter(const WallHeadingOptions& options, double start_heading)
    : options_(options), start_heading_(start_heading), state_(startState()) {}

WallHeadingFilter::State WallHeadingFilter::startState() const {
  State state;
  state.heading = start_heading_;
  state.covariance = Eigen::MatrixXd::Zero(2, 2);
  return state;
}

double WallHeadingFilter::update(double turn_rad, double driven_m, std::vector<WallSegment> segments) {
  frames_.push_back({turn_rad, driven_m, std::move(segments)});
  if (step(state_, frames_.back(), true)) {
    state_ = startState();
    for (const Frame& frame : frames_) step(state_, frame, false);
  }
  return state_.heading;
}

bool WallHeadingFilter::step(State& state, const Frame& frame, bool vote) {
  state.heading += state.turn_scale * frame.turn_rad;
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Identity(state.covariance.rows(), state.covariance.cols());
  jacobian(0, 1) = frame.turn_rad;
  state.covariance = jacobian * state.covariance * jacobian.transpose();
  state.covariance(0, 0) += mrpt::square(mrpt::DEG2RAD(options_.heading_noise_deg_per_frame)) +
                            mrpt::square(options_.heading_noise_per_rad * frame.turn_rad) +
                            mrpt::square(mrpt::DEG2RAD(options_.heading_noise_deg_per_m) * frame.driven_m);
  const double min_sigma = mrpt::DEG2RAD(options_.min_sigma_deg);
  const double max_correction = mrpt::DEG2RAD(options_.max_correction_deg);
  const double spread = mrpt::DEG2RAD(options_.new_direction_spread_deg);
  bool confirmed = false;
  state.frame_corrections = 0;
  for (const WallSegment& segment : frame.segments) {
    const double sigma = std::max(segment.sigma_rad, min_sigma);
    const double world = pairDirection(segment.direction_rad + state.heading);
    size_t nearest = state.directions.size();
    double innovation = M_PI;
    for (size_t i = 0; i < state.directions.size(); ++i) {
      const double difference = pairAngleDifference(world, state.directions[i]);
      if (std::abs(difference) < std::abs(innovation)) {
        innovation = difference;
        nearest = i;
      }
    }
    if (std::abs(innovation) > max_correction) {
      const auto first_sighting = std::find_if(confirmed_.begin(), confirmed_.end(), [&](double direction) {
        return std::abs(pairAngleDifference(world, direction)) <= spread &&
               std::none_of(state.directions.begin(), state.directions.end(), [&](double known) {
                 return std::abs(pairAngleDifference(direction, known)) <= max_correction;
               });
      });
      if (first_sighting != confirmed_.end()) {
        // Measured from the heading, the direction shares its error, plus its own.
        const Eigen::Index n = state.covariance.rows();
        state.covariance.conservativeResize(n + 1, n + 1);
        state.covariance.row(n).head(n) = state.covariance.row(0).head(n);
        state.covariance.col(n).head(n) = state.covariance.col(0).head(n);
        state.covariance(n, n) = state.covariance(0, 0) + sigma * sigma;
        // Until a direction can be seen again after a turn the scale cannot be told, and letting
        // its doubt into the heading before would keep the first direction from being taken up.
        if (state.directions.empty()) state.covariance(1, 1) = mrpt::square(options_.turn_scale_sigma);
        state.directions.push_back(world);
      } else if (vote) {
        confirmed = voteFor(world, std::sqrt(state.covariance(0, 0) + sigma * sigma)) || confirmed;
      }
      continue;
    }
    const Eigen::Index d = 2 + static_cast<Eigen::Index>(nearest);
    const double innovation_variance = state.covariance(0, 0) + state.covariance(d, d) -
                                       2.0 * state.covariance(0, d) + sigma * sigma;
    if (innovation * innovation > mrpt::square(options_.gate_sigmas) * innovation_variance) continue;
    // The segment's direction predicted from the state is direction - heading: H = [-1 0 .. 1 ..],
    // and the innovation (world - direction) is measured minus predicted.
    const Eigen::VectorXd gain = (state.covariance.col(d) - state.covariance.col(0)) / innovation_variance;
    state.heading += gain(0) * innovation;
    state.turn_scale += gain(1) * innovation;
    for (size_t i = 0; i < state.directions.size(); ++i) {
      state.directions[i] = pairDirection(state.directions[i] + gain(2 + static_cast<Eigen::Index>(i)) * innovation);
    }
    const Eigen::RowVectorXd h_covariance = state.covariance.row(d) - state.covariance.row(0);
    state.covariance -= gain * h_covariance;
    ++state.frame_corrections;
  }
  return confirmed;
}

bool WallHeadingFilter::voteFor(double world_direction, double sigma) {
  const double spread = mrpt::DEG2RAD(options_.new_direction_spread_deg);
  if (sigma > spread) return false;  // the heading is too unsure to tell where the wall runs
  const double weight = 1.0 / (sigma * sigma);
  for (Candidate& candidate : candidates_) {
    const double difference = pairAngleDifference(world_direction, candidate.direction);
    if (std::abs(difference) > spread) continue;
    candidate.direction = pairDirection(candidate.direction + difference * weight / (candidate.weight + weight));
    candidate.weight += weight;
    if (++candidate.segments < options_.new_direction_segments) return false;
    confirmed_.push_back(candidate.direction);
    candidates_.clear();
    return true;
  }
  candidates_.push_back({world_direction, weight, 1});
  return false;
}

}  // namespace stereonav
