#pragma once

#include <opencv2/core.hpp>

#include <cstddef>
#include <vector>

#include "column_projection/column_projector.h"
#include "column_projection/disparity_scan.h"
#include "disparity/disparity_engine.h"
#include "disparity/stereo_frame.h"
#include "mapping/stage_times.h"
#include "observations/rig_frame.h"
#include "rig/camera_rig.h"
#include "spike_removal/spike_filter.h"

namespace stereonav {

// The front half of the per-frame pipeline (paper figure 5 a-c): a rig frame's disparity image
// (section 2.2), spikes removed (section 4.2), projected column by column onto the floor
// (section 3.3). The images, disparity and mask stay in buffers kept between frames; the results
// of the last frame can be read until the next call.
class DisparityScanner {
 public:
  DisparityScanner(const CameraRig& rig, const StereoOptions& stereo,
                   const SpikeRemovalOptions& spike_removal, const ProjectionOptions& projection);

  // Matches the frame's images as taken by this scanner's rig (its calibration may come from the
  // ini rather than the frame). Throws std::invalid_argument if the frame has another number of
  // cameras or another image size.
  const DisparityScan& scan(const RigFrame& frame, StageTimes& times);

  const CameraRig& rig() const { return rig_; }
  const cv::Mat1b& referenceGrey() const { return stereo_frame_.reference; }
  // After spike removal; kInvalidDisparity where stereo or spike removal found nothing usable.
  const cv::Mat1f& disparity() const { return disparity_; }
  // 255 where spike removal invalidated a matched pixel (paper figure 6d), else 0.
  const cv::Mat1b& rejected() const { return rejected_; }
  const DisparityScan& lastScan() const { return scan_; }
  // Pixels of the last frame with a stereo match, and those of them spike removal kept.
  size_t matchedPixels() const { return matched_pixels_; }
  size_t keptPixels() const { return kept_pixels_; }

 private:
  // `grey` = the image itself if it is grey, else its conversion in `buffer`.
  void toGrey(const cv::Mat& image, cv::Mat1b& buffer, cv::Mat1b& grey) const;

  CameraRig rig_;
  StereoMatcher matcher_;
  SpikeFilter spike_filter_;
  ColumnProjector projector_;
  float range_top_;
  std::vector<cv::Mat1b> grey_buffers_;  // camera 0 = reference, k = secondary k-1
  StereoFrame stereo_frame_;
  cv::Mat1f disparity_;
  cv::Mat1b rejected_;
  DisparityScan scan_;
  size_t matched_pixels_ = 0;
  size_t kept_pixels_ = 0;
};

}  // namespace stereonav
