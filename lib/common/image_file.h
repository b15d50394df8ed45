#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>  // the flags: cv::ImreadModes

#include <string>

namespace stereonav {

// The image at `path`, read by cv::imread with `flags` (cv::ImreadModes). Throws
// std::runtime_error "<path>: <why>", one line, when the file is missing, cannot be decoded, or
// is refused by OpenCV (a header claiming more pixels than OpenCV reads, say); OpenCV's own
// warning is not printed, since a missing file is found before OpenCV is asked.
cv::Mat readImageFile(const std::string& path, int flags);

// Writes `image` to `path` atomically (temporary file + rename), the format from the extension.
// Throws std::runtime_error naming the file when it cannot be written.
void writeImageFile(const std::string& path, const cv::Mat& image);

}  // namespace stereonav
