#pragma once

#include <mrpt/poses/CPose2D.h>

#include <opencv2/core.hpp>

#include <cstddef>
#include <string>

#include "mapping/disparity_scanner.h"
#include "mapping/mapping_options.h"
#include "occupancy_grid/disparity_scan_inserter.h"
#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// One picture per frame showing how the frame became map evidence, tile by tile as in paper
// figures 5 and 6:
//   (a) the reference image;
//   (b) the disparity image, colour-mapped (blue far .. red near), invalid pixels white and the
//       surfaces spike removal rejected magenta (figure 6d shows them black);
//   (c) the maximum disparity of each column inside the robot's body volume, as a strip
//       aligned with (b)'s columns, its lower third black under blind columns (columns that
//       see none of the nearest floor, ProjectionOptions::near_floor_m);
//   (d) depth per column, metres (figure 5d);
//   (e) this frame's OCC (black) and CLEAR (white) regions seen from above, unknown grey, with
//       the camera at the bottom looking up (figure 5e).
class DebugPanelRenderer {
 public:
  DebugPanelRenderer(const MappingOptions& options, const CameraRig& rig);

  // The panel of the scanner's last frame. `frame_index` and `robot_pose` go into the caption.
  cv::Mat3b render(const DisparityScanner& scanner, size_t frame_index,
                   const mrpt::poses::CPose2D& robot_pose);

 private:
  cv::Mat3b disparityTile(const DisparityScanner& scanner) const;
  cv::Mat3b columnStripTile(const DisparityScan& scan) const;
  cv::Mat3b depthPlotTile(const DisparityScan& scan) const;
  cv::Mat3b topDownTile(const DisparityScan& scan, int size);
  cv::Vec3b disparityColour(float disparity) const;

  CameraRig rig_;
  StereoOptions stereo_;
  double range_m_;
  int image_scale_;  // reference pixels -> panel pixels, so small images stay readable
  GridLimits view_limits_;
  DisparityTaggedGrid regions_;        // this frame's regions only, in the camera's floor frame
  DisparityScanInserter inserter_;
  cv::Mat3b colour_table_;             // 256 colours of the disparity colour map
};

// "<directory>/panel_000042.png", written atomically.
void saveDebugPanel(const cv::Mat3b& panel, const std::string& directory, size_t frame_index);

}  // namespace stereonav
