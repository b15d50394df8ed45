#include "disparity/disparity_io.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "common/atomic_file.h"
#include "common/image_file.h"
#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

bool hasExtension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  std::string tail = path.substr(path.size() - extension.size());
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == extension;
}

bool littleEndianHost() {
  const uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

void swapBytes(float& value) {
  unsigned char bytes[4];
  std::memcpy(bytes, &value, 4);
  std::swap(bytes[0], bytes[3]);
  std::swap(bytes[1], bytes[2]);
  std::memcpy(&value, bytes, 4);
}

}  // namespace

void writeDisparityPfm(const std::string& path, const cv::Mat1f& disparity) {
  std::ostringstream out;
  // A negative scale marks little-endian data; rows go bottom to top.
  out << "Pf\n" << disparity.cols << " " << disparity.rows << "\n" << (littleEndianHost() ? "-1" : "1") << "\n";
  for (int y = disparity.rows - 1; y >= 0; --y) {
    out.write(reinterpret_cast<const char*>(disparity.ptr<float>(y)),
              static_cast<std::streamsize>(disparity.cols * sizeof(float)));
  }
  writeStringAtomically(path, out.str());
}

cv::Mat1f readDisparityPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string magic;
  int width = 0, height = 0;
  double scale = 0.0;
  if (!(in >> magic >> width >> height >> scale) || magic != "Pf" || width <= 0 || height <= 0 || scale == 0.0) {
    throw std::runtime_error(path + ": not a single-channel PFM file");
  }
  in.get();  // the single whitespace before the data
  cv::Mat1f disparity(height, width);
  const bool swap = (scale < 0) != littleEndianHost();
  for (int y = height - 1; y >= 0; --y) {
    float* row = disparity.ptr<float>(y);
    if (!in.read(reinterpret_cast<char*>(row), static_cast<std::streamsize>(width * sizeof(float)))) {
      throw std::runtime_error(path + ": PFM data is truncated");
    }
    if (swap) {
      for (int x = 0; x < width; ++x) swapBytes(row[x]);
    }
  }
  return disparity;
}

void writeDisparityPng16(const std::string& path, const cv::Mat1f& disparity) {
  cv::Mat1w encoded(disparity.size());
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      const float d = disparity(y, x);
      if (!isValidDisparity(d)) {
        encoded(y, x) = 0;
        continue;
      }
      const long value = std::lround(256.0 * d);
      if (d < 0 || value > 65535) {
        throw std::runtime_error(path + ": disparity " + std::to_string(d) + " does not fit a 16-bit PNG (0..255.99)");
      }
      encoded(y, x) = static_cast<ushort>(std::max(1L, value));
    }
  }
  writeImageAtomically(path, encoded);
}

cv::Mat1f readDisparityPng16(const std::string& path) {
  const cv::Mat encoded = readImageFile(path, cv::IMREAD_UNCHANGED);
  if (encoded.type() != CV_16UC1) throw std::runtime_error(path + ": not a 16-bit single-channel PNG");
  cv::Mat1f disparity;
  encoded.convertTo(disparity, CV_32F, 1.0 / 256.0);
  disparity.setTo(kInvalidDisparity, encoded == 0);
  return disparity;
}

void writeDisparityImage(const std::string& path, const cv::Mat1f& disparity) {
  if (hasExtension(path, ".pfm")) return writeDisparityPfm(path, disparity);
  if (hasExtension(path, ".png")) return writeDisparityPng16(path, disparity);
  throw std::runtime_error(path + ": unknown disparity file type (expected .pfm or .png)");
}

cv::Mat1f readDisparityImage(const std::string& path) {
  if (hasExtension(path, ".pfm")) return readDisparityPfm(path);
  if (hasExtension(path, ".png")) return readDisparityPng16(path);
  throw std::runtime_error(path + ": unknown disparity file type (expected .pfm or .png)");
}

cv::Mat3b colourDisparity(const cv::Mat1f& disparity, double max_disparity) {
  cv::Mat1b grey;
  disparity.convertTo(grey, CV_8U, 255.0 / std::max(max_disparity, 1e-6));
  cv::Mat3b colour;
  cv::applyColorMap(grey, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar::all(255), disparity == kInvalidDisparity);
  return colour;
}

void writeDisparityColourPng(const std::string& path, const cv::Mat1f& disparity, double max_disparity) {
  const cv::Mat3b colour = colourDisparity(disparity, max_disparity);
  writeImageAtomically(path, colour);
}

}  // namespace stereonav
