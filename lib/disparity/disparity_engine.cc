#include "disparity/disparity_engine.h"

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
  match.disparity.copyTo(disparity);
  if (options_.texture_threshold > 0) {
    textureMap(frame.reference, options_.window, options_.texture_sigma, texture_);
    rejectLowTexture(disparity, texture_, options_.texture_threshold);
  }
  if (options_.uniqueness_threshold < 1.0) rejectAmbiguousMatches(disparity, match, options_.uniqueness_threshold);
  if (!match.second_score.empty()) rejectIndistinctMatches(disparity, match, options_.second_best_ratio);
  if (!options_.left_right_check) return;
  const SecondaryCamera& first = frame.secondaries.front().camera;
  if (!match.reverse_disparity.empty()) {
    rejectInconsistentMatches(disparity, match.reverse_disparity, first, options_.left_right_max_diff);
    return;
  }
  // Several cameras, or one off the horizontal: the swapped rig is matched again.
  if (!swapped_matcher_) swapped_matcher_ = std::make_unique<SadMatcher>(options_);
  const SadMatch& swapped = swapped_matcher_->match(swapReferenceWithFirstSecondary(frame));
  rejectInconsistentMatches(disparity, swapped.disparity, first, options_.left_right_max_diff);
}

cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options) {
  cv::Mat1f disparity;
  StereoMatcher(options).compute(frame, disparity);
  return disparity;
}

}  // namespace stereonav
