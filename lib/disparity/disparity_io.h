#pragma once

#include <opencv2/core.hpp>

#include <string>

namespace stereonav {

// Disparity image files. All writers go through writeFileAtomically; readers and writers throw
// std::runtime_error naming the file on any failure.

// Middlebury PFM: 32-bit float, little-endian, rows stored bottom to top, invalid = +inf (the same
// value as kInvalidDisparity).
void writeDisparityPfm(const std::string& path, const cv::Mat1f& disparity);
cv::Mat1f readDisparityPfm(const std::string& path);

// KITTI 16-bit PNG: value = round(256 * d), 0 = invalid. A valid disparity below 1/512 is stored as
// 1 (1/256 px) so that it stays valid; disparities of 256 or more cannot be stored.
void writeDisparityPng16(const std::string& path, const cv::Mat1f& disparity);
cv::Mat1f readDisparityPng16(const std::string& path);

// Either of the above, chosen by the extension (.pfm or .png).
void writeDisparityImage(const std::string& path, const cv::Mat1f& disparity);
cv::Mat1f readDisparityImage(const std::string& path);

// For people: disparities 0..max_disparity through the turbo colour map (far = blue, near = red),
// invalid pixels white.
cv::Mat3b colourDisparity(const cv::Mat1f& disparity, double max_disparity);
void writeDisparityColourPng(const std::string& path, const cv::Mat1f& disparity, double max_disparity);

}  // namespace stereonav
