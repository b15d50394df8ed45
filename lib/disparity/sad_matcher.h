#pragma once

#include <opencv2/core.hpp>

#include "disparity/stereo_frame.h"
#include "disparity/stereo_options.h"

namespace stereonav {

// Winner-takes-all output of the multi-baseline SAD engine, before validation. For every
// reference pixel: the disparity whose combined window score is lowest (the smallest such
// disparity on ties), that score, and the sum of the scores of all candidates (the paper's
// "quality of match" test divides the first by the last). Pixels that no secondary camera sees
// at every candidate disparity (image borders) are kInvalidDisparity with zero scores.
struct SadMatch {
  cv::Mat1f disparity;
  cv::Mat1i best_score;
  cv::Mat1i score_sum;
};

// Multi-baseline SAD stereo (paper section 2.2, after Okutomi and Kanade): every view is
// prefiltered (options.prefilter), then for each candidate disparity the absolute differences
// between the reference and each secondary camera's pixel at (x - bx*d, y - by*d) are summed
// over a options.window square and combined across cameras (options.combination).
// Near the borders, where some cameras' candidates leave the image, the remaining cameras are
// used. Uses options.min_disparity, max_disparity, window, prefilter*, combination, subpixel and
// threads; validation is separate (disparity/validation.h).
SadMatch matchSad(const StereoFrame& frame, const StereoOptions& options);

}  // namespace stereonav
