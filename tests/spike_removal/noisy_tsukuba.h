#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>

#include "disparity/disparity_image.h"

namespace stereonav {

// A realistic disparity image for spike removal at 320x240: the tsukuba ground truth (paper-era
// indoor scene) scaled to that size, with what a real-time matcher adds to it (paper section 4.1):
// sub-pixel jitter, unmatched holes, single-pixel mismatches and coherent mismatch blobs at
// disparities spread over the whole range. Disparities are multiples of 1/16 so the same image
// converts exactly to OpenCV's CV_16S fixed-point disparity (x16).
inline cv::Mat1f noisyTsukubaDisparity(uint64_t seed) {
  const std::string path = std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/truedisp.row3.col3.pgm";
  const cv::Mat1b truth = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (truth.empty()) throw std::runtime_error("cannot read " + path);
  cv::Mat1b small;
  cv::resize(truth, small, cv::Size(320, 240), 0, 0, cv::INTER_NEAREST);
  const float scale = 320.0f / truth.cols / 16.0f;  // grey/16 is disparity at 384 wide

  cv::RNG rng(seed);
  cv::Mat1f disparity(small.size());
  for (int y = 0; y < small.rows; ++y) {
    for (int x = 0; x < small.cols; ++x) {
      const float jitter = rng.uniform(-2, 3) / 16.0f;
      disparity(y, x) = small(y, x) == 0
                            ? kInvalidDisparity
                            : std::round((small(y, x) * scale + jitter) * 16.0f) / 16.0f;
    }
  }
  const auto random_disparity = [&rng] { return rng.uniform(0, 16 * 14) / 16.0f; };
  for (int hole = 0; hole < 40; ++hole) {
    const cv::Rect rect(rng.uniform(0, 310), rng.uniform(0, 230), rng.uniform(2, 10),
                        rng.uniform(2, 10));
    disparity(rect).setTo(kInvalidDisparity);
  }
  for (int blob = 0; blob < 80; ++blob) {
    const cv::Rect rect(rng.uniform(0, 312), rng.uniform(0, 232), rng.uniform(2, 8),
                        rng.uniform(2, 8));
    disparity(rect).setTo(random_disparity());
  }
  for (int speck = 0; speck < 320 * 240 / 50; ++speck) {
    disparity(rng.uniform(0, 240), rng.uniform(0, 320)) = random_disparity();
  }
  return disparity;
}

// The same image as OpenCV's fixed-point disparity (x16), invalid pixels as `invalid_value`.
inline cv::Mat1s toFixedPointDisparity(const cv::Mat1f& disparity, int16_t invalid_value) {
  cv::Mat1s fixed(disparity.size());
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      const float d = disparity(y, x);
      fixed(y, x) = isValidDisparity(d) ? static_cast<int16_t>(cvRound(d * 16.0f)) : invalid_value;
    }
  }
  return fixed;
}

}  // namespace stereonav
