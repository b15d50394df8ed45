#include "disparity/stereo_frame.h"

#include <stdexcept>
#include <string>

namespace stereonav {

void checkStereoFrame(const StereoFrame& frame) {
  if (frame.reference.empty()) throw std::invalid_argument("stereo frame: empty reference image");
  if (frame.secondaries.empty()) throw std::invalid_argument("stereo frame: no secondary view");
  for (size_t i = 0; i < frame.secondaries.size(); ++i) {
    const SecondaryView& view = frame.secondaries[i];
    const std::string which = "stereo frame: secondary view " + std::to_string(i + 1);
    if (view.image.size() != frame.reference.size()) {
      throw std::invalid_argument(which + " is " + std::to_string(view.image.cols) + "x" +
                                  std::to_string(view.image.rows) + ", the reference " +
                                  std::to_string(frame.reference.cols) + "x" +
                                  std::to_string(frame.reference.rows));
    }
    if (view.camera.bx == 0.0 && view.camera.by == 0.0) {
      throw std::invalid_argument(which + " has baseline (0, 0)");
    }
  }
}

StereoFrame swapReferenceWithFirstSecondary(const StereoFrame& frame) {
  const SecondaryCamera first = frame.secondaries.front().camera;
  StereoFrame swapped;
  swapped.reference = frame.secondaries.front().image;
  swapped.secondaries.push_back({frame.reference, {-first.bx, -first.by}});
  for (size_t i = 1; i < frame.secondaries.size(); ++i) {
    const SecondaryView& view = frame.secondaries[i];
    swapped.secondaries.push_back({view.image, {view.camera.bx - first.bx, view.camera.by - first.by}});
  }
  return swapped;
}

}  // namespace stereonav
