#include "mapping/disparity_scanner.h"

#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>

#include "disparity/disparity_engine.h"

namespace stereonav {
namespace {

size_t countValid(const cv::Mat1f& disparity) {
  size_t count = 0;
  for (int y = 0; y < disparity.rows; ++y) {
    const float* row = disparity[y];
    for (int x = 0; x < disparity.cols; ++x) count += isValidDisparity(row[x]) ? 1 : 0;
  }
  return count;
}

}  // namespace

DisparityScanner::DisparityScanner(const CameraRig& rig, const StereoOptions& stereo,
                                   const SpikeRemovalOptions& spike_removal,
                                   const ProjectionOptions& projection)
    : rig_(rig), matcher_(stereo), spike_filter_(spike_removal), projector_(rig, projection),
      range_top_(static_cast<float>(stereo.max_disparity)) {
  grey_buffers_.resize(rig_.secondaries.size() + 1);
  stereo_frame_.secondaries.resize(rig_.secondaries.size());
  for (size_t i = 0; i < rig_.secondaries.size(); ++i) {
    stereo_frame_.secondaries[i].camera = rig_.secondaries[i];
  }
}

void DisparityScanner::toGrey(const cv::Mat& image, cv::Mat1b& buffer, cv::Mat1b& grey) const {
  const PinholeCamera& camera = rig_.reference;
  if (image.cols != camera.width || image.rows != camera.height) {
    throw std::invalid_argument("frame image is " + std::to_string(image.cols) + "x" +
                                std::to_string(image.rows) + ", the rig's camera is " +
                                std::to_string(camera.width) + "x" +
                                std::to_string(camera.height));
  }
  if (image.type() == CV_8UC1) {
    grey = image;  // shares the frame's pixels
  } else {
    cv::cvtColor(image, buffer, cv::COLOR_BGR2GRAY);
    grey = buffer;
  }
}

const DisparityScan& DisparityScanner::scan(const RigFrame& frame, StageTimes& times) {
  if (frame.secondaries.size() != rig_.secondaries.size()) {
    throw std::invalid_argument("frame has " + std::to_string(frame.secondaries.size() + 1) +
                                " cameras, the rig " +
                                std::to_string(rig_.secondaries.size() + 1));
  }
  {
    ScopedStageTimer timer(times, PipelineStage::kGrey);
    toGrey(frame.reference, grey_buffers_[0], stereo_frame_.reference);
    for (size_t i = 0; i < frame.secondaries.size(); ++i) {
      toGrey(frame.secondaries[i], grey_buffers_[i + 1], stereo_frame_.secondaries[i].image);
    }
  }
  {
    ScopedStageTimer timer(times, PipelineStage::kStereo);
    matcher_.compute(stereo_frame_, disparity_);
  }
  {
    ScopedStageTimer timer(times, PipelineStage::kSpikeRemoval);
    spike_filter_.apply(disparity_, rejected_);
  }
  {
    ScopedStageTimer timer(times, PipelineStage::kProjection);
    scan_ = projector_.project(disparity_);
    scan_.range_top = range_top_;
  }
  kept_pixels_ = countValid(disparity_);
  matched_pixels_ = kept_pixels_ + static_cast<size_t>(cv::countNonZero(rejected_));
  return scan_;
}

}  // namespace stereonav
