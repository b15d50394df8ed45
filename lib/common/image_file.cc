#include "common/image_file.h"

#include "common/atomic_file.h"

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <stdexcept>

namespace stereonav {

cv::Mat readImageFile(const std::string& path, int flags) {
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": no such image file");
  cv::Mat image;
  try {
    image = cv::imread(path, flags);
  } catch (const cv::Exception& error) {
    throw std::runtime_error(path + ": cannot read the image (" + error.err + ")");
  }
  if (image.empty()) throw std::runtime_error(path + ": cannot read the image (not a format OpenCV decodes)");
  return image;
}

void writeImageFile(const std::string& path, const cv::Mat& image) {
  writeFileAtomically(path, [&](const std::string& temporary) {
    if (!cv::imwrite(temporary, image)) throw std::runtime_error(path + ": cannot write the image");
  });
}

}  // namespace stereonav
