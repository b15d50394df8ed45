#pragma once

#include <opencv2/core.hpp>

#include "disparity/stereo_frame.h"
#include "disparity/stereo_options.h"

namespace stereonav {

// The stereo stage: the disparity image of one rig frame in the reference camera, invalid pixels
// kInvalidDisparity. Backend sad: multi-baseline SAD (matchSad) followed by the texture and
// uniqueness tests of paper section 2.2 and, if enabled, the left-right check against the first
// secondary camera. Backends bm/sgbm: matchOpenCv. Throws std::invalid_argument for a bad frame
// and ConfigError for bad options (including max_disparity >= the image width).
cv::Mat1f computeDisparity(const StereoFrame& frame, const StereoOptions& options);

}  // namespace stereonav
