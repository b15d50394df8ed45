#include "disparity/disparity_engine.h"

#include <string>

#include "disparity/opencv_matchers.h"
#include "disparity/validation.h"

namespace stereonav {

StereoMatcher::StereoMatcher(const StereoOptions& options)
    : options_(options),
      reference_matcher_(options),
      swapped_matcher_(options.left_right_check ? std::make_unique<SadMatcher>(options) : nullptr) {}

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
  rejectAmbiguousMatches(disparity, match, options_.uniqueness_threshold);
  if (swapped_matcher_) {
    const SadMatch& swapped = swapped_matcher_->match(swapReferenceWithFirstSecondary(frame));
    rejectInconsistentMatches(disparity, swapped.disparity, frame.secondaries.front().camera,
                              options_.left_right_max_diff);
  }
}

cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options) {
  cv::Mat1f disparity;
  StereoMatcher(options).compute(frame, disparity);
  return disparity;
}

}  // namespace stereonav
