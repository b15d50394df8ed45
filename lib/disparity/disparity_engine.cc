#include "disparity/disparity_engine.h"

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <string>

#include "disparity/opencv_matchers.h"
#include "disparity/validation.h"

namespace stereonav {

StereoMatcher::StereoMatcher(const StereoOptions& options)
    : options_(options),
      reference_matcher_(options),
      swapped_matcher_(nullptr) {}

void StereoMatcher::compute(const StereoFrame& frame, cv::Mat1f& disparity) {
  checkStereoFrame(frame);
  if (options_.max_disparity >= frame.reference.cols) {
    throw ConfigError("[stereo] max_disparity: " + std::to_string(options_.max_disparity) +
                      " is not smaller than the image width " + std::to_string(frame.reference.cols));
  }
  if (options_.backend != StereoBackend::kSad) {
    matchOpenCv(frame, options_).copyTo(disparity);
    return;
  }
  const SadMatch& match = reference_matcher_.match(frame);
  if (options_.texture_threshold > 0) textureMap(frame.reference, options_.window, options_.texture_sigma, texture_);
  const SecondaryCamera& first = frame.secondaries.front().camera;
  // The left-right check reads the reverse match of the same scores, or else (several cameras,
  // or one off the horizontal) the swapped rig matched again.
  const cv::Mat1f* swapped = nullptr;
  if (options_.left_right_check) {
    swapped = &match.reverse_disparity;
    if (match.reverse_disparity.empty()) {
      if (!swapped_matcher_) swapped_matcher_ = std::make_unique<SadMatcher>(options_);
      swapped = &swapped_matcher_->match(swapReferenceWithFirstSecondary(frame)).disparity;
    }
  }
  // Each test writes only the pixels of its rows, so stripes of rows are validated in parallel,
  // as they were matched: done on one thread, this part would cap what more threads gain.
  disparity.create(match.disparity.size());
  const int height = disparity.rows, stripes = std::min(options_.threads, height);
  const auto validate = [&](const cv::Range& range) {
    const cv::Range rows(height * range.start / stripes, height * range.end / stripes);
    match.disparity.rowRange(rows).copyTo(disparity.rowRange(rows));
    if (options_.texture_threshold > 0) rejectLowTexture(disparity, texture_, options_.texture_threshold, rows);
    if (options_.uniqueness_threshold < 1.0) {
      rejectAmbiguousMatches(disparity, match, options_.uniqueness_threshold, rows);
    }
    if (!match.second_score.empty()) rejectIndistinctMatches(disparity, match, options_.second_best_ratio, rows);
    if (swapped) rejectInconsistentMatches(disparity, *swapped, first, options_.left_right_max_diff, rows);
    if (options_.fattening_min_step > 0) {
      rejectFattenedEdges(disparity, frame.reference, options_.window, options_.fattening_min_jump,
                          options_.fattening_min_step, rows);
    }
  };
  if (stripes == 1) {
    validate(cv::Range(0, 1));
  } else {
    cv::parallel_for_(cv::Range(0, stripes), validate, stripes);
  }
}

cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options) {
  cv::Mat1f disparity;
  StereoMatcher(options).compute(frame, disparity);
  return disparity;
}

}  // namespace stereonav
