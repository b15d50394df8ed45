#include "disparity/disparity_engine.h"

#include <string>

#include "disparity/opencv_matchers.h"
#include "disparity/sad_matcher.h"
#include "disparity/validation.h"

namespace stereonav {

cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options) {
  checkStereoFrame(frame);
  validateStereoOptions(options);
  if (options.max_disparity >= frame.reference.cols) {
    throw ConfigError("[stereo] max_disparity: " + std::to_string(options.max_disparity) +
                      " is not smaller than the image width " + std::to_string(frame.reference.cols));
  }
  if (options.backend != StereoBackend::kSad) return matchOpenCv(frame, options);

  const SadMatch match = matchSad(frame, options);
  cv::Mat1f disparity = match.disparity;
  if (options.texture_threshold > 0) {
    rejectLowTexture(disparity, textureMap(frame.reference, options.window, options.texture_sigma),
                     options.texture_threshold);
  }
  rejectAmbiguousMatches(disparity, match, options.uniqueness_threshold);
  if (options.left_right_check) {
    const SadMatch swapped = matchSad(swapReferenceWithFirstSecondary(frame), options);
    rejectInconsistentMatches(disparity, swapped.disparity, frame.secondaries.front().camera,
                              options.left_right_max_diff);
  }
  return disparity;
}

}  // namespace stereonav
