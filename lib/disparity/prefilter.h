#pragma once

#include <opencv2/core.hpp>

#include "disparity/stereo_options.h"

namespace stereonav {

// Laplacian of Gaussian of an 8-bit image, in float: Gaussian blur with `sigma`, then the 3x3
// Laplacian. Used for the texture test (paper section 2.2) and the kLog prefilter. `log` is
// reused if it already has the right size.
void laplacianOfGaussian(const cv::Mat1b& image, double sigma, cv::Mat1f& log);

// The image the SAD engine compares: a copy for kNone, otherwise the filter response clipped to
// [-cap, cap] and offset by cap (so 0..2*cap), like cv::StereoBM's x-Sobel prefilter.
void prefilterImage(const cv::Mat1b& image, Prefilter prefilter, int cap, double log_sigma, cv::Mat1b& filtered);

// Largest absolute difference two prefiltered pixels can have (bounds the SAD accumulators).
int maxPrefilteredDifference(Prefilter prefilter, int cap);

}  // namespace stereonav
