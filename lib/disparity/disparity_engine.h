#pragma once

#include <opencv2/core.hpp>

#include <memory>

#include "disparity/sad_matcher.h"
#include "disparity/stereo_frame.h"
#include "disparity/stereo_options.h"

namespace stereonav {

// The stereo stage: the disparity image of rig frames in the reference camera, invalid pixels
// kInvalidDisparity. Backend sad: multi-baseline SAD (SadMatcher) followed by the texture and
// uniqueness tests of paper section 2.2 and, if enabled, the left-right check against the first
// secondary camera. Backends bm/sgbm: matchOpenCv. One matcher keeps its buffers between
// frames, so a stream of same-size frames allocates nothing.
class StereoMatcher {
 public:
  explicit StereoMatcher(const StereoOptions& options);  // throws ConfigError for bad options

  const StereoOptions& options() const { return options_; }

  // Writes the disparity image of `frame` into `disparity` (reallocated only when its size
  // changes). Throws std::invalid_argument for a bad frame and ConfigError if max_disparity is
  // not smaller than the image width.
  void compute(const StereoFrame& frame, cv::Mat1f& disparity);

 private:
  StereoOptions options_;
  SadMatcher reference_matcher_;
  // For the left-right check where the reference match has no reverse disparity (created on first use).
  std::unique_ptr<SadMatcher> swapped_matcher_;
  cv::Mat1f texture_;
};

// One frame with a fresh StereoMatcher.
cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options);

}  // namespace stereonav
