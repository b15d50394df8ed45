#include "evaluation/score_overlay.h"

#include <opencv2/imgcodecs.hpp>

#include <stdexcept>

#include "common/atomic_file.h"
#include "evaluation/map_comparison.h"

namespace stereonav {

cv::Mat3b drawScoreOverlay(const RosMap& map, const RosMap& truth, const MapScoreOptions& options) {
  const MapComparison cells = compareOnTruthCells(map, truth, options);
  const cv::Vec3b kOutside(128, 128, 128), kFree(255, 255, 255), kMappedFree(200, 255, 200),
      kFound(0, 0, 0), kMissed(255, 0, 0), kNotCounted(80, 80, 80), kCorrect(0, 170, 0), kWrong(0, 0, 255),
      kFalseFree(255, 0, 255);
  cv::Mat3b image(truth.height(), truth.width());
  for (int iy = 0; iy < truth.height(); ++iy) {
    for (int ix = 0; ix < truth.width(); ++ix) {
      cv::Vec3b colour = kOutside;
      if (cells.truth_occupied(iy, ix)) {
        colour = !cells.scored_obstacles(iy, ix) ? kNotCounted : cells.near_map_obstacle(iy, ix) ? kFound : kMissed;
      } else if (truth.cell(ix, iy) == CellClass::kFree) {
        colour = cells.map_free(iy, ix) ? kMappedFree : kFree;
      }
      if (cells.map_occupied(iy, ix)) colour = cells.near_truth_obstacle(iy, ix) ? kCorrect : kWrong;
      if (cells.scored_obstacles(iy, ix) && cells.map_free(iy, ix)) colour = kFalseFree;
      image(truth.height() - 1 - iy, ix) = colour;
    }
  }
  return image;
}

void saveScoreOverlay(const RosMap& map, const RosMap& truth, const MapScoreOptions& options,
                      const std::string& path) {
  const cv::Mat3b image = drawScoreOverlay(map, truth, options);
  writeImageAtomically(path, image);
}

}  // namespace stereonav
