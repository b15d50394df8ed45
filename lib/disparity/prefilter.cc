#include "disparity/prefilter.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace stereonav {

void laplacianOfGaussian(const cv::Mat1b& image, double sigma, cv::Mat1f& log) {
  thread_local cv::Mat1f blurred;  // scratch, reused from call to call
  // The kernel spans +-4 sigma, as cv::GaussianBlur's does for float images; filtering the 8-bit
  // image straight into float gives the same values as converting it first, one pass sooner.
  const int size = 2 * static_cast<int>(std::ceil(4 * sigma)) + 1;
  const cv::Mat kernel = cv::getGaussianKernel(size, sigma, CV_32F);
  cv::sepFilter2D(image, blurred, CV_32F, kernel, kernel, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
  cv::Laplacian(blurred, log, CV_32F, 1, 1.0, 0.0, cv::BORDER_REPLICATE);
}

void prefilterImage(const cv::Mat1b& image, Prefilter prefilter, int cap, double log_sigma, cv::Mat1b& filtered) {
  if (prefilter == Prefilter::kNone) {
    image.copyTo(filtered);
    return;
  }
  thread_local cv::Mat1s sobel;  // scratch, reused from call to call
  thread_local cv::Mat1f log;
  const cv::Mat* response = &sobel;
  if (prefilter == Prefilter::kXSobel) {
    cv::Sobel(image, sobel, CV_16S, 1, 0, 3, 1.0, 0.0, cv::BORDER_REPLICATE);
  } else {
    laplacianOfGaussian(image, log_sigma, log);
    response = &log;
  }
  // convertTo saturates below at 0, which is the lower clip; the upper one is explicit.
  response->convertTo(filtered, CV_8U, 1.0, cap);
  cv::min(filtered, 2 * cap, filtered);
}

int maxPrefilteredDifference(Prefilter prefilter, int cap) {
  return prefilter == Prefilter::kNone ? 255 : 2 * cap;
}

}  // namespace stereonav
