#include "disparity/prefilter.h"

#include <opencv2/imgproc.hpp>

namespace stereonav {

cv::Mat1f laplacianOfGaussian(const cv::Mat1b& image, double sigma) {
  cv::Mat1f blurred, log;
  image.convertTo(blurred, CV_32F);
  cv::GaussianBlur(blurred, blurred, cv::Size(), sigma, sigma, cv::BORDER_REPLICATE);
  cv::Laplacian(blurred, log, CV_32F, 1, 1.0, 0.0, cv::BORDER_REPLICATE);
  return log;
}

cv::Mat1b prefilterImage(const cv::Mat1b& image, Prefilter prefilter, int cap, double log_sigma) {
  if (prefilter == Prefilter::kNone) return image;
  cv::Mat response;
  if (prefilter == Prefilter::kXSobel) {
    cv::Sobel(image, response, CV_16S, 1, 0, 3, 1.0, 0.0, cv::BORDER_REPLICATE);
  } else {
    response = laplacianOfGaussian(image, log_sigma);
  }
  // convertTo saturates below at 0, which is the lower clip; the upper one is explicit.
  cv::Mat1b clipped;
  response.convertTo(clipped, CV_8U, 1.0, cap);
  cv::min(clipped, 2 * cap, clipped);
  return clipped;
}

int maxPrefilteredDifference(Prefilter prefilter, int cap) {
  return prefilter == Prefilter::kNone ? 255 : 2 * cap;
}

}  // namespace stereonav
