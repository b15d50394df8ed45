#include "disparity/disparity_evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/image_file.h"
#include "disparity/disparity_image.h"

namespace stereonav {

cv::Mat1f loadMiddleburyGroundTruth(const std::string& path, double scale) {
  if (!(scale > 0)) throw std::invalid_argument(path + ": ground-truth scale must be positive");
  const cv::Mat raw = readImageFile(path, cv::IMREAD_ANYDEPTH | cv::IMREAD_GRAYSCALE);
  if (raw.depth() != CV_8U && raw.depth() != CV_16U) {
    throw std::runtime_error(path + ": ground truth must be an 8- or 16-bit grey image");
  }
  cv::Mat1f ground_truth;
  raw.convertTo(ground_truth, CV_32F, 1.0 / scale);
  ground_truth.setTo(kInvalidDisparity, raw == 0);
  return ground_truth;
}

cv::Mat1b loadEvaluationMask(const std::string& path) {
  const cv::Mat raw = readImageFile(path, cv::IMREAD_GRAYSCALE);
  return raw == 255;
}

cv::Mat1b nonOccludedMask(const cv::Mat1f& ground_truth, const SecondaryCamera& camera, float tolerance) {
  const int width = ground_truth.cols, height = ground_truth.rows;
  // The largest disparity landing on each pixel of the camera's image.
  cv::Mat1f front(height, width, -std::numeric_limits<float>::infinity());
  const auto landing = [&](int x, int y, float d, int& xs, int& ys) {
    xs = static_cast<int>(std::lround(x - camera.bx * d));
    ys = static_cast<int>(std::lround(y - camera.by * d));
    return xs >= 0 && xs < width && ys >= 0 && ys < height;
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float d = ground_truth(y, x);
      int xs = 0, ys = 0;
      if (isValidDisparity(d) && landing(x, y, d, xs, ys)) front(ys, xs) = std::max(front(ys, xs), d);
    }
  }
  cv::Mat1b visible(height, width, uchar{0});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float d = ground_truth(y, x);
      int xs = 0, ys = 0;
      if (isValidDisparity(d) && landing(x, y, d, xs, ys) && front(ys, xs) <= d + tolerance) visible(y, x) = 255;
    }
  }
  return visible;
}

DisparityEvaluation evaluateDisparity(const cv::Mat1f& disparity, const cv::Mat1f& ground_truth, int border,
                                      const cv::Mat1b& mask) {
  if (disparity.size() != ground_truth.size()) {
    throw std::invalid_argument("evaluation: disparity and ground truth differ in size");
  }
  if (!mask.empty() && mask.size() != ground_truth.size()) {
    throw std::invalid_argument("evaluation: mask and ground truth differ in size");
  }
  DisparityEvaluation result;
  int bad_0_5 = 0, bad_1 = 0, bad_2 = 0;
  double abs_error_sum = 0.0, inlier_square_sum = 0.0;
  for (int y = border; y < disparity.rows - border; ++y) {
    for (int x = border; x < disparity.cols - border; ++x) {
      const float truth = ground_truth(y, x);
      if (!isValidDisparity(truth) || (!mask.empty() && mask(y, x) == 0)) continue;
      ++result.known_pixels;
      const float d = disparity(y, x);
      if (!isValidDisparity(d)) continue;
      ++result.valid_pixels;
      const double error = std::abs(static_cast<double>(d) - truth);
      abs_error_sum += error;
      bad_0_5 += error > 0.5;
      bad_1 += error > 1.0;
      bad_2 += error > 2.0;
      if (error <= 1.0) inlier_square_sum += error * error;
    }
  }
  if (result.known_pixels > 0) result.density = static_cast<double>(result.valid_pixels) / result.known_pixels;
  if (result.valid_pixels > 0) {
    result.bad_0_5 = static_cast<double>(bad_0_5) / result.valid_pixels;
    result.bad_1 = static_cast<double>(bad_1) / result.valid_pixels;
    result.bad_2 = static_cast<double>(bad_2) / result.valid_pixels;
    result.mean_abs_error = abs_error_sum / result.valid_pixels;
    const int inliers = result.valid_pixels - bad_1;
    if (inliers > 0) result.inlier_rms_error = std::sqrt(inlier_square_sum / inliers);
  }
  return result;
}

}  // namespace stereonav
