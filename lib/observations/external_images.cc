#include "observations/external_images.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "common/atomic_file.h"

namespace stereonav {

std::string externalImagesDirectoryFor(const std::string& rawlog_path) {
  std::filesystem::path path(rawlog_path);
  return (path.parent_path() / (path.stem().string() + "_Images")).string();
}

std::string findExternalImagesDirectory(const std::string& rawlog_path) {
  const std::string ours = externalImagesDirectoryFor(rawlog_path);
  const std::string stem = ours.substr(0, ours.size() - std::string("_Images").size());
  for (const std::string& spelling : {ours, stem + "_images", stem + "_IMAGES"}) {
    if (std::filesystem::is_directory(spelling)) return spelling;
  }
  return ours;
}

void storeImageExternally(mrpt::img::CImage& image, const std::string& directory,
                          const std::string& file_name) {
  const std::string path = directory + "/" + file_name;
  const cv::Mat pixels = image.asCvMatRef();
  writeImageAtomically(path, pixels);
  image.setExternalStorage(file_name);
}

cv::Mat imagePixels(const mrpt::img::CImage& image, const std::string& images_directory) {
  if (!image.isExternallyStored()) return image.asCvMatRef();
  const std::filesystem::path file(image.getExternalStorageFile());
  const std::filesystem::path path = file.is_absolute() ? file : images_directory / file;
  if (!std::filesystem::is_regular_file(path)) return {};  // spares OpenCV's warning
  return cv::imread(path.string(), cv::IMREAD_UNCHANGED);
}

}  // namespace stereonav
