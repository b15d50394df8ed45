#include "observations/rig_frame.h"

#include <stdexcept>
#include <string>

namespace stereonav {

void checkRigFrame(const RigFrame& frame) {
  const auto& camera = frame.rig.reference;
  if (frame.secondaries.size() != frame.rig.secondaries.size()) {
    throw std::invalid_argument("rig frame: " + std::to_string(frame.secondaries.size()) +
                                " secondary images for a rig with " +
                                std::to_string(frame.rig.secondaries.size()) +
                                " secondary cameras");
  }
  const auto check = [&](const cv::Mat& image, const std::string& which) {
    if (image.cols != camera.width || image.rows != camera.height) {
      throw std::invalid_argument("rig frame: " + which + " image is " +
                                  std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                  ", the rig's camera is " + std::to_string(camera.width) + "x" +
                                  std::to_string(camera.height));
    }
    if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3) ||
        image.type() != frame.reference.type()) {
      throw std::invalid_argument("rig frame: " + which +
                                  " image must be 8-bit grey or BGR, like the reference image");
    }
  };
  check(frame.reference, "reference");
  for (size_t i = 0; i < frame.secondaries.size(); ++i) {
    check(frame.secondaries[i], "secondary " + std::to_string(i));
  }
}

}  // namespace stereonav
