#pragma once

#include <mrpt/img/CImage.h>

#include <opencv2/core.hpp>
#include <string>

namespace stereonav {

// MRPT's delayed-load images: an observation stores only a file name, relative to a folder named
// "<rawlog stem>_Images" beside the rawlog (what rawlog-grabber writes and RawLogViewer,
// rawlog-edit and CRawlog::detectImagesDirectory look for).

// The folder a rawlog's external images are written to: "dir/run.rawlog" -> "dir/run_Images".
std::string externalImagesDirectoryFor(const std::string& rawlog_path);

// The images folder of an existing rawlog: "<stem>_Images", or the "_images" / "_IMAGES"
// spellings other recorders use if only one of those exists.
std::string findExternalImagesDirectory(const std::string& rawlog_path);

// Writes `image` losslessly (PNG) as `directory`/`file_name`, atomically, and turns `image` into
// a reference to that file (`file_name`, relative to the images folder).
void storeImageExternally(mrpt::img::CImage& image, const std::string& directory,
                          const std::string& file_name);

// The pixels of `image`: shared with it when embedded, read from `images_directory` (or the
// absolute path it names) when externally stored. Returns an empty cv::Mat if that file cannot
// be read. Unlike CImage's own lazy loading this needs no process-wide images path.
cv::Mat imagePixels(const mrpt::img::CImage& image, const std::string& images_directory);

}  // namespace stereonav
