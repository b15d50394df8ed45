#pragma once

#include <opencv2/core.hpp>

#include <string>

namespace stereonav {

// Scores of a disparity image against ground truth, Middlebury style. Only pixels with known
// ground truth outside the ignored border count.
struct DisparityEvaluation {
  int known_pixels = 0;         // ground truth known
  int valid_pixels = 0;         // of those, a valid disparity was produced
  double density = 0.0;         // valid_pixels / known_pixels
  double bad_1 = 0.0;           // share of valid pixels with |error| > 1.0
  double bad_2 = 0.0;           // share of valid pixels with |error| > 2.0
  double mean_abs_error = 0.0;  // over valid pixels
};

// A Middlebury ground-truth image (8- or 16-bit grey): disparity = value / scale, 0 = unknown
// (returned as kInvalidDisparity). Throws std::runtime_error naming the file.
cv::Mat1f loadMiddleburyGroundTruth(const std::string& path, double scale);

// Compares `disparity` with `ground_truth` (unknown = kInvalidDisparity), ignoring `border`
// pixels on every side (18 for the classic Middlebury evaluation).
DisparityEvaluation evaluateDisparity(const cv::Mat1f& disparity, const cv::Mat1f& ground_truth, int border = 18);

}  // namespace stereonav
