#include "localization/wall_heading_filter.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

namespace stereonav {

double perpendicularPairDifference(double a, double b) {
  double d = std::remainder(a - b, M_PI / 2);
  if (d >= M_PI / 4) d -= M_PI / 2;
  return d;
}

namespace {

double pairDirection(double a) { return perpendicularPairDifference(a, 0.0); }

}  // namespace

WallHeadingFilter::WallHeadingFilter(const WallHeadingOptions& options, double start_heading)
    : options_(options), start_heading_(start_heading), state_(startState(false)) {}

WallHeadingFilter::State WallHeadingFilter::startState(bool direction_confirmed) const {
  State state;
  state.heading = start_heading_;
  state.prediction = {start_heading_, 0.0};
  state.covariance = Eigen::MatrixXd::Zero(2, 2);
  // Until a direction is known the scale's doubt would only widen the heading's, and keep the
  // votes for the first direction from agreeing. Once one is, the filter runs again from the
  // start with it, so that the heading at a direction's first sighting carries the scale's error
  // of the turns before, and learning the scale later corrects the direction too.
  if (direction_confirmed) state.covariance(1, 1) = mrpt::square(options_.turn_scale_sigma);
  return state;
}

WallHeadingFilter::State WallHeadingFilter::rerun() {
  State state = startState(!confirmed_.empty());
  for (const Frame& frame : frames_) step(state, frame, false);
  return state;
}

double WallHeadingFilter::update(double turn_rad, double driven_m, std::vector<WallSegment> segments,
                                 const TurnDoubt& doubt) {
  if (doubt.earlier_turns_scale) {
    // The doubtful turns are corrected where they were taken (the walls first seen after them
    // with them), and this frame's turn loses the correction odometry added to it.
    const double scale = *doubt.earlier_turns_scale;
    for (Frame& frame : frames_) {
      if (frame.turn_scale_sigma_rad == 0.0) continue;
      turn_rad -= (scale - 1.0) * frame.turn_rad;
      frame.turn_rad *= scale;
      frame.turn_scale_sigma_rad = 0.0;
    }
    state_ = rerun();
  }
  frames_.push_back({turn_rad, driven_m, std::move(segments), doubt.sigma_rad, doubt.scale_sigma_rad});
  if (step(state_, frames_.back(), true)) state_ = rerun();
  return state_.heading;
}

bool WallHeadingFilter::step(State& state, const Frame& frame, bool vote) {
  const double variance_before = state.covariance(0, 0);
  state.heading += state.turn_scale * frame.turn_rad;
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Identity(state.covariance.rows(), state.covariance.cols());
  jacobian(0, 1) = frame.turn_rad;
  state.covariance = jacobian * state.covariance * jacobian.transpose();
  state.covariance(0, 0) += mrpt::square(mrpt::DEG2RAD(options_.heading_noise_deg_per_frame)) +
                            mrpt::square(options_.heading_noise_per_rad * frame.turn_rad) +
                            mrpt::square(mrpt::DEG2RAD(options_.heading_noise_deg_per_m) * frame.driven_m) +
                            mrpt::square(frame.turn_sigma_rad) + mrpt::square(frame.turn_scale_sigma_rad);
  state.prediction = {state.heading, state.covariance(0, 0)};
  const double min_sigma = mrpt::DEG2RAD(options_.min_sigma_deg);
  const double max_correction = mrpt::DEG2RAD(options_.max_correction_deg);
  const double spread = mrpt::DEG2RAD(options_.new_direction_spread_deg);
  // A held segment is dropped once odometry may have turned the heading more than `spread` since.
  for (HeldSegment& held : state.held) held.added_variance += state.covariance(0, 0) - variance_before;
  state.held.erase(std::remove_if(state.held.begin(), state.held.end(),
                                  [&](const HeldSegment& held) { return held.added_variance > spread * spread; }),
                   state.held.end());
  const bool unsure = state.covariance(0, 0) > spread * spread;
  bool confirmed = false;
  state.frame_corrections = 0;
  for (const WallSegment& segment : frame.segments) {
    const double sigma = std::max(segment.sigma_rad, min_sigma);
    const double world = pairDirection(segment.direction_rad + state.heading);
    size_t nearest = state.directions.size();
    double innovation = M_PI;
    for (size_t i = 0; i < state.directions.size(); ++i) {
      const double difference = perpendicularPairDifference(world, state.directions[i]);
      if (std::abs(difference) < std::abs(innovation)) {
        innovation = difference;
        nearest = i;
      }
    }
    if (std::abs(innovation) > max_correction) {
      const auto first_sighting = std::find_if(confirmed_.begin(), confirmed_.end(), [&](double direction) {
        return std::abs(perpendicularPairDifference(world, direction)) <= spread &&
               std::none_of(state.directions.begin(), state.directions.end(), [&](double known) {
                 return std::abs(perpendicularPairDifference(direction, known)) <= max_correction;
               });
      });
      if (first_sighting != confirmed_.end()) {
        // Measured from the heading, the direction shares its error, plus its own.
        const Eigen::Index n = state.covariance.rows();
        state.covariance.conservativeResize(n + 1, n + 1);
        state.covariance.row(n).head(n) = state.covariance.row(0).head(n);
        state.covariance.col(n).head(n) = state.covariance.col(0).head(n);
        state.covariance(n, n) = state.covariance(0, 0) + sigma * sigma;
        state.directions.push_back(world);
      } else if (vote) {
        confirmed = voteFor(world, std::sqrt(state.covariance(0, 0) + sigma * sigma)) || confirmed;
      }
      continue;
    }
    if (innovation * innovation > mrpt::square(options_.gate_sigmas) * innovationVariance(state, nearest, sigma)) {
      continue;
    }
    if (unsure || std::abs(innovation) > spread) {
      state.held.push_back({nearest, innovation, sigma, 0.0});
    } else {
      correct(state, nearest, innovation, sigma);
    }
  }
  if (state.held.empty()) return confirmed;
  // One askew segment (a chair, a desk, a person) within the gate could turn the heading by as
  // much as the gate is wide: a segment that would turn it by more than `spread`, or any while
  // the heading is unsure, corrects it only once enough, in this frame or the last few, agree.
  std::vector<size_t> agreeing;
  for (const HeldSegment& held : state.held) {
    std::vector<size_t> members;
    for (size_t i = 0; i < state.held.size(); ++i) {
      if (std::abs(state.held[i].innovation - held.innovation) <= spread) members.push_back(i);
    }
    if (members.size() > agreeing.size()) agreeing = std::move(members);
  }
  if (static_cast<int>(agreeing.size()) < options_.agreeing_segments) return confirmed;
  // Each correction moves the heading and the directions, and with them the held innovations.
  for (const size_t i : agreeing) {
    correct(state, state.held[i].direction, state.held[i].innovation, state.held[i].sigma);
  }
  state.held.clear();
  return confirmed;
}

double WallHeadingFilter::innovationVariance(const State& state, size_t direction, double sigma) {
  // The segment's direction predicted from the state is direction - heading: H = [-1 0 .. 1 ..].
  const Eigen::Index d = 2 + static_cast<Eigen::Index>(direction);
  return state.covariance(0, 0) + state.covariance(d, d) - 2.0 * state.covariance(0, d) + sigma * sigma;
}

void WallHeadingFilter::correct(State& state, size_t direction, double innovation, double sigma) const {
  const Eigen::Index d = 2 + static_cast<Eigen::Index>(direction);
  // The innovation (world - direction) is measured minus predicted.
  const Eigen::VectorXd gain =
      (state.covariance.col(d) - state.covariance.col(0)) / innovationVariance(state, direction, sigma);
  state.heading += gain(0) * innovation;
  state.turn_scale += gain(1) * innovation;
  for (size_t i = 0; i < state.directions.size(); ++i) {
    state.directions[i] = pairDirection(state.directions[i] + gain(2 + static_cast<Eigen::Index>(i)) * innovation);
  }
  const Eigen::RowVectorXd h_covariance = state.covariance.row(d) - state.covariance.row(0);
  state.covariance -= gain * h_covariance;
  // Held segments were measured against the heading and directions before this correction.
  for (HeldSegment& held : state.held) {
    held.innovation += gain(0) * innovation - gain(2 + static_cast<Eigen::Index>(held.direction)) * innovation;
  }
  ++state.frame_corrections;
}

bool WallHeadingFilter::voteFor(double world_direction, double sigma) {
  const double spread = mrpt::DEG2RAD(options_.new_direction_spread_deg);
  if (sigma > spread) return false;  // the heading is too unsure to tell where the wall runs
  const double weight = 1.0 / (sigma * sigma);
  for (Candidate& candidate : candidates_) {
    const double difference = perpendicularPairDifference(world_direction, candidate.direction);
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
