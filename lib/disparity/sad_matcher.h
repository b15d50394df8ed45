#pragma once

#include <opencv2/core.hpp>

#include <memory>

#include "disparity/stereo_frame.h"
#include "disparity/stereo_options.h"

namespace stereonav {

// Winner-takes-all output of the multi-baseline SAD engine, before validation. For every
// reference pixel: the disparity whose combined window score is lowest (the smallest such
// disparity on ties), that score, and the sum of the scores of all candidates (the paper's
// "quality of match" test divides the first by the last; zero when
// options.uniqueness_threshold is 1, the test off). With options.second_best_ratio < 1,
// also the lowest score of the candidates more than one disparity away from the best (INT_MAX if
// there is none); otherwise second_score is empty. Pixels that no secondary camera sees at every
// candidate disparity (image borders) are kInvalidDisparity with zero scores.
// With options.left_right_check on a binocular rig whose camera sits at (1, 0) or (-1, 0),
// reverse_disparity is the winner-takes-all disparity of every pixel of the secondary image, taken
// from the same window scores (as cv::StereoBM's disp12MaxDiff check: no second match; a pixel
// near the border takes the best of the candidates the reference sees); otherwise it is empty.
struct SadMatch {
  cv::Mat1f disparity;
  cv::Mat1i best_score;
  cv::Mat1i score_sum;
  cv::Mat1i second_score;
  cv::Mat1f reverse_disparity;
};

// The scanline aggregation (CostAggregation::kScanline) keeps its paths and their sums in bytes,
// with saturating arithmetic, which takes twice the candidates per vector instruction: the window
// scores are divided by 2^shift, the smallest power of two that brings the largest possible window
// score of `cameras` cameras under 512, and so are the jump costs. A window scoring more than half
// the largest possible score, or a sum of the two paths past 255, saturates at 255: such a
// candidate is far worse than any match the distinctiveness test keeps (docs/stereo.md measures
// the accuracy). Returns -1 where the paths keep the scores' own width: semi-global paths, more
// than 256 candidates, window scores beyond 16 bits, or a large-jump cost above 255 after the
// division.
int scanlinePathShift(const StereoOptions& options, int cameras);

// Multi-baseline SAD stereo (paper section 2.2, after Okutomi and Kanade): every view is
// prefiltered (options.prefilter), then for each candidate disparity the absolute differences
// between the reference and each secondary camera's pixel at (x - bx*d, y - by*d) are summed
// over a options.window square and combined across cameras (options.combination).
// Near the borders, where some cameras' candidates leave the image, the remaining cameras are
// used. Uses options.min_disparity, max_disparity, window, prefilter*, combination, subpixel and
// threads; validation is separate (disparity/validation.h). Like cv::StereoBM, one matcher keeps
// its buffers from frame to frame, so a stream of same-size frames allocates nothing.
class SadMatcher {
 public:
  explicit SadMatcher(const StereoOptions& options);  // throws ConfigError for bad options
  ~SadMatcher();
  SadMatcher(const SadMatcher&) = delete;
  SadMatcher& operator=(const SadMatcher&) = delete;

  // The match of `frame`. Its images are the matcher's own: the next call overwrites them
  // (clone them to keep them). Throws std::invalid_argument for a bad frame.
  const SadMatch& match(const StereoFrame& frame);

 private:
  struct Workspace;
  StereoOptions options_;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace stereonav
