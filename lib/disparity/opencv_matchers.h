#pragma once

#include <opencv2/core.hpp>

#include "disparity/stereo_frame.h"
#include "disparity/stereo_options.h"

namespace stereonav {

// cv::StereoBM (backend bm) or cv::StereoSGBM (backend sgbm) on a binocular frame whose camera
// is one unit baseline along an image axis ({1,0}, {-1,0}, {0,1}, {0,-1}); the images are flipped
// and/or transposed so that OpenCV's left/right convention holds, and the result is brought back
// to the reference frame as a disparity image (float pixels, kInvalidDisparity where OpenCV found
// none). Uses min/max_disparity, window, prefilter_cap, subpixel (otherwise rounded to whole
// pixels), left_right_check (as disp12MaxDiff) and the opencv_* options; StereoBM's prefilter is
// its x-Sobel for prefilter = xsobel and its normalised response otherwise.
// Throws std::invalid_argument for other rigs.
cv::Mat1f matchOpenCv(const StereoFrame& frame, const StereoOptions& options);

}  // namespace stereonav
