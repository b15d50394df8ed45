#include "localization/scan_matcher.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "localization/scan_points.h"

namespace stereonav {
namespace {

// A pose offset from the prior, in steps of the search grid.
struct Offset {
  double x = 0.0;
  double y = 0.0;
  double phi = 0.0;
};

class PoseScorer {
 public:
  PoseScorer(const std::vector<ScanPoint>& points, const ObstacleDistanceField& field,
             const mrpt::poses::CPose2D& prior, const PriorSigma& prior_sigma,
             const LocalizationOptions& options)
      : points_(points),
        field_(field),
        prior_(prior),
        outlier_(options.outlier_probability),
        log_outlier_(std::log(options.outlier_probability)),
        inlier_weight_(1.0 - options.outlier_probability),
        prior_precision_xy_(1.0 / mrpt::square(prior_sigma.position_m)),
        prior_precision_phi_(1.0 / mrpt::square(prior_sigma.heading_rad)) {
    rotated_.resize(points.size());
  }

  // Readings turned by the prior's heading plus `dphi`; the log-likelihoods that follow use them.
  void rotate(double dphi) {
    const double c = std::cos(prior_.phi() + dphi), s = std::sin(prior_.phi() + dphi);
    for (size_t i = 0; i < points_.size(); ++i) {
      rotated_[i] = {c * points_[i].x - s * points_[i].y, s * points_[i].x + c * points_[i].y};
    }
  }

  double logLikelihood(double dx, double dy) const {
    double sum = 0.0;
    const double x0 = prior_.x() + dx, y0 = prior_.y() + dy;
    for (size_t i = 0; i < points_.size(); ++i) {
      const double d = field_.distance(x0 + rotated_[i][0], y0 + rotated_[i][1]);
      const double z = d / points_[i].sigma;
      sum += z > 6.0 ? log_outlier_ : std::log(outlier_ + inlier_weight_ * std::exp(-0.5 * z * z));
    }
    return sum;
  }

  double logPrior(double dx, double dy, double dphi) const {
    return -0.5 * ((dx * dx + dy * dy) * prior_precision_xy_ + dphi * dphi * prior_precision_phi_);
  }

  int matchedPoints(const mrpt::poses::CPose2D& pose) const {
    int matched = 0;
    for (const ScanPoint& point : points_) {
      const mrpt::poses::CPose2D world = pose + mrpt::poses::CPose2D(point.x, point.y, 0.0);
      if (field_.distance(world.x(), world.y()) < 3.0 * point.sigma) ++matched;
    }
    return matched;
  }

 private:
  const std::vector<ScanPoint>& points_;
  const ObstacleDistanceField& field_;
  mrpt::poses::CPose2D prior_;
  double outlier_;
  double log_outlier_;
  double inlier_weight_;
  double prior_precision_xy_;
  double prior_precision_phi_;
  std::vector<std::array<double, 2>> rotated_;
};

}  // namespace

std::vector<ScanPoint> matchablePoints(const mrpt::obs::CObservation2DRangeScan& scan,
                                       double focal_baseline_px_m,
                                       const LocalizationOptions& options) {
  std::vector<ScanPoint> points;
  double last_x = std::numeric_limits<double>::infinity(), last_y = last_x;
  for (const ScanReadingPoint& reading : scanPointsWithin(scan, options.max_range_m)) {
    if (std::hypot(reading.x - last_x, reading.y - last_y) < options.point_spacing_m) continue;
    last_x = reading.x;
    last_y = reading.y;
    const double range_sigma = focal_baseline_px_m > 0.0 ? reading.range_m * reading.range_m /
                                                               focal_baseline_px_m * options.disparity_sigma_px
                                                         : 0.0;
    points.push_back({reading.x, reading.y, std::max(options.min_point_sigma_m, range_sigma)});
  }
  return points;
}

PriorSigma priorSigmaAfter(const mrpt::poses::CPose2D& motion, const LocalizationOptions& options) {
  return {options.prior_sigma_m + options.prior_sigma_m_per_m * motion.norm(),
          mrpt::DEG2RAD(options.prior_sigma_deg) +
              options.prior_sigma_per_rad * std::abs(mrpt::math::wrapToPi(motion.phi()))};
}

namespace {

// The search lattice of one match: offsets are searched in steps and compared normalised by the
// window (at least one step) in each direction, so spreads of metres and radians compare.
struct SearchLattice {
  explicit SearchLattice(const LocalizationOptions& options)
      : step_xy(options.step_m),
        step_phi(mrpt::DEG2RAD(options.step_deg)),
        steps_xy(static_cast<int>(std::round(options.window_m / options.step_m))),
        steps_phi(static_cast<int>(std::round(options.window_deg / options.step_deg))),
        scale(std::max(steps_xy, 1) * step_xy, std::max(steps_xy, 1) * step_xy,
              std::max(steps_phi, 1) * step_phi) {}
  double step_xy, step_phi;
  int steps_xy, steps_phi;
  Eigen::Vector3d scale;
};

struct BestOffset {
  Offset offset;
  double score = -std::numeric_limits<double>::infinity();

  void consider(const Offset& candidate, double candidate_score) {
    if (candidate_score <= score) return;
    score = candidate_score;
    offset = candidate;
  }
};

using NormalisedLikelihoods = std::vector<std::pair<Eigen::Vector3d, double>>;

// The best pose under likelihood x prior over the whole window; every likelihood is kept for
// the spread.
BestOffset coarseSearch(PoseScorer& scorer, const SearchLattice& lattice,
                        NormalisedLikelihoods& likelihoods) {
  likelihoods.reserve(static_cast<size_t>((2 * lattice.steps_xy + 1) * (2 * lattice.steps_xy + 1) *
                                          (2 * lattice.steps_phi + 1)));
  BestOffset best;
  for (int k = -lattice.steps_phi; k <= lattice.steps_phi; ++k) {
    const double dphi = k * lattice.step_phi;
    scorer.rotate(dphi);
    for (int j = -lattice.steps_xy; j <= lattice.steps_xy; ++j) {
      for (int i = -lattice.steps_xy; i <= lattice.steps_xy; ++i) {
        const double dx = i * lattice.step_xy, dy = j * lattice.step_xy;
        const double log_likelihood = scorer.logLikelihood(dx, dy);
        likelihoods.emplace_back(Eigen::Vector3d(dx, dy, dphi).cwiseQuotient(lattice.scale),
                                 log_likelihood);
        best.consider({dx, dy, dphi}, log_likelihood + scorer.logPrior(dx, dy, dphi));
      }
    }
  }
  return best;
}

// The covariance of the offset under the likelihood alone: how well the scan pins each direction.
Eigen::Matrix3d likelihoodSpread(const NormalisedLikelihoods& likelihoods) {
  double max_log_likelihood = -std::numeric_limits<double>::infinity();
  for (const auto& entry : likelihoods) max_log_likelihood = std::max(max_log_likelihood, entry.second);
  double weight_sum = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();
  for (const auto& [offset, log_likelihood] : likelihoods) {
    const double weight = std::exp(log_likelihood - max_log_likelihood);
    weight_sum += weight;
    mean += weight * offset;
    second_moment += weight * offset * offset.transpose();
  }
  mean /= weight_sum;
  return second_moment / weight_sum - mean * mean.transpose();
}

// Around the coarse best, a quarter step apart.
void fineSearch(PoseScorer& scorer, const SearchLattice& lattice, BestOffset& best) {
  const Offset coarse = best.offset;
  const double fine_xy = lattice.step_xy / 4, fine_phi = lattice.step_phi / 4;
  for (int k = -4; k <= 4; ++k) {
    const double dphi = coarse.phi + k * fine_phi;
    scorer.rotate(dphi);
    for (int j = -4; j <= 4; ++j) {
      for (int i = -4; i <= 4; ++i) {
        const double dx = coarse.x + i * fine_xy, dy = coarse.y + j * fine_xy;
        best.consider({dx, dy, dphi}, scorer.logLikelihood(dx, dy) + scorer.logPrior(dx, dy, dphi));
      }
    }
  }
}

// The correction kept along the directions the scan pins down only (spread below max_spread).
Eigen::Vector3d constrainedCorrection(const Offset& best, const SearchLattice& lattice,
                                      const LocalizationOptions& options, ScanMatch& match) {
  const Eigen::Vector3d correction =
      Eigen::Vector3d(best.x, best.y, best.phi).cwiseQuotient(lattice.scale);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> directions(match.spread);
  Eigen::Vector3d kept = Eigen::Vector3d::Zero();
  for (int d = 0; d < 3; ++d) {
    if (std::sqrt(std::max(directions.eigenvalues()(d), 0.0)) >= options.max_spread) continue;
    const Eigen::Vector3d direction = directions.eigenvectors().col(d);
    kept += direction.dot(correction) * direction;
    ++match.constrained_directions;
  }
  return kept.cwiseProduct(lattice.scale);
}

}  // namespace

ScanMatch matchScan(const std::vector<ScanPoint>& points, const ObstacleDistanceField& field,
                    const mrpt::poses::CPose2D& prior, const PriorSigma& prior_sigma,
                    const LocalizationOptions& options) {
  ScanMatch match;
  match.pose = prior;
  match.points = static_cast<int>(points.size());
  if (match.points < options.min_matched_points || !field.hasObstacles()) return match;

  PoseScorer scorer(points, field, prior, prior_sigma, options);
  const SearchLattice lattice(options);
  NormalisedLikelihoods likelihoods;
  BestOffset best = coarseSearch(scorer, lattice, likelihoods);
  match.spread = likelihoodSpread(likelihoods);
  fineSearch(scorer, lattice, best);

  const Eigen::Vector3d kept = constrainedCorrection(best.offset, lattice, options, match);
  const mrpt::poses::CPose2D corrected(prior.x() + kept.x(), prior.y() + kept.y(),
                                       mrpt::math::wrapToPi(prior.phi() + kept.z()));
  match.matched_points = scorer.matchedPoints(corrected);
  if (match.matched_points < options.min_matched_points ||
      match.matched_points < options.min_matched_fraction * match.points ||
      match.constrained_directions == 0) {
    match.matched_points = scorer.matchedPoints(prior);
    return match;
  }
  match.pose = corrected;
  match.corrected = true;
  return match;
}

}  // namespace stereonav
