#pragma once

#include <opencv2/core.hpp>

#include <string>

#include "rig/camera_rig.h"

namespace stereonav {

// Scores of a disparity image against ground truth, Middlebury style. Only pixels with known
// ground truth outside the ignored border count.
struct DisparityEvaluation {
  int known_pixels = 0;         // ground truth known
  int valid_pixels = 0;         // of those, a valid disparity was produced
  double density = 0.0;         // valid_pixels / known_pixels
  double bad_0_5 = 0.0;         // share of valid pixels with |error| > 0.5 (sub-pixel precision)
  double bad_1 = 0.0;           // share of valid pixels with |error| > 1.0
  double bad_2 = 0.0;           // share of valid pixels with |error| > 2.0
  double mean_abs_error = 0.0;  // over valid pixels
  // Root mean square error over the valid pixels with |error| <= 1: the precision of the matches
  // that are right, which the bad-pixel shares cannot show (sub-pixel fits move errors within 1).
  double inlier_rms_error = 0.0;
};

// A Middlebury ground-truth image (8- or 16-bit grey): disparity = value / scale, 0 = unknown
// (returned as kInvalidDisparity). Throws std::runtime_error naming the file.
cv::Mat1f loadMiddleburyGroundTruth(const std::string& path, double scale);

// A Middlebury evaluation mask (nonocc.png, all.png, disc.png): 255 = evaluated, any other value
// (0 or the 128 some masks use for occlusions) = not. Returns 255 / 0. Throws std::runtime_error
// naming the file.
cv::Mat1b loadEvaluationMask(const std::string& path);

// The pixels of `ground_truth` that `camera` sees, for pairs that come without a non-occluded mask:
// the truth is forward-warped into that camera (pixel (x, y) at disparity d lands at
// (x - bx*d, y - by*d), rounded) and a pixel is occluded if it lands outside the image or where
// another pixel with a disparity more than `tolerance` larger lands too (it is in front). Middlebury
// derives its masks the same way. 255 = visible and known, 0 = occluded or unknown.
cv::Mat1b nonOccludedMask(const cv::Mat1f& ground_truth, const SecondaryCamera& camera, float tolerance = 1.0f);

// Compares `disparity` with `ground_truth` (unknown = kInvalidDisparity), ignoring `border`
// pixels on every side (18 for the classic Middlebury evaluation) and, if `mask` is not empty,
// the pixels where it is 0.
DisparityEvaluation evaluateDisparity(const cv::Mat1f& disparity, const cv::Mat1f& ground_truth, int border = 18,
                                      const cv::Mat1b& mask = cv::Mat1b());

}  // namespace stereonav
