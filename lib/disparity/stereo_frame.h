#pragma once

#include <opencv2/core.hpp>

#include <vector>

#include "rig/camera_rig.h"

namespace stereonav {

// One rectified secondary image and where its camera sits (rig/camera_rig.h: a point at
// disparity d seen at (x, y) in the reference appears at (x - bx*d, y - by*d) here).
struct SecondaryView {
  cv::Mat1b image;
  SecondaryCamera camera;
};

// What the matcher sees of one rig frame: the 8-bit grey reference image and N >= 1 secondary
// views of the same size. Binocular {1,0}; Triclops L {-1,0},{0,-1}; Middlebury's collinear
// {-2,0},{-1,0},{1,0},{2,0}; fractional baselines such as {0.5,0} are interpolated.
struct StereoFrame {
  cv::Mat1b reference;
  std::vector<SecondaryView> secondaries;
};

// Throws std::invalid_argument if the reference is empty, there is no secondary view, a view's
// size differs from the reference's, or a camera sits on the reference (0, 0).
void checkStereoFrame(const StereoFrame& frame);

// The same rig seen from the first secondary camera: it becomes the reference, the old
// reference sits at -b1 and every other camera at b - b1. Disparities keep the unit baseline, so
// a point at disparity d for the reference has disparity d here as well.
StereoFrame swapReferenceWithFirstSecondary(const StereoFrame& frame);

}  // namespace stereonav
