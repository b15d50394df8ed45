#pragma once

#include <opencv2/core.hpp>

#include <limits>

namespace stereonav {

// A disparity image is a cv::Mat1f in the reference camera's frame, in pixels for the rig's unit
// baseline. Invalid pixels (rejected by a validation test or a filter, or never matched) hold
// kInvalidDisparity, the same +inf that Middlebury's PFM files use, so 0 is always a real
// disparity (a point at infinity), never "no data".
constexpr float kInvalidDisparity = std::numeric_limits<float>::infinity();

inline bool isValidDisparity(float disparity) { return disparity != kInvalidDisparity; }

}  // namespace stereonav
