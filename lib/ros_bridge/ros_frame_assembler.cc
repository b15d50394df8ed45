#include "ros_bridge/ros_frame_assembler.h"

#include <algorithm>
#include <stdexcept>

#include "observations/rig_observations.h"
#include "ros_bridge/ros_camera_messages.h"

namespace stereonav {
namespace {

std::vector<std::string> labelsInRigOrder(const RosHeadOptions& options) {
  if (options.cameras < 2 || options.cameras > kMaxRosCameras) {
    throw std::invalid_argument("a ROS stereo head has 2 or 3 cameras (left, right, top), not " +
                                std::to_string(options.cameras));
  }
  std::vector<std::string> labels{kRosCameraNames[0], kRosCameraNames[1]};
  if (options.reference_is_right) std::swap(labels[0], labels[1]);
  for (size_t camera = 2; camera < options.cameras; ++camera) labels.push_back(kRosCameraNames[camera]);
  return labels;
}

}  // namespace

RosHeadOptions rosHeadOptions(const MappingOptions& options) {
  RosHeadOptions head;
  head.max_time_difference_s = options.pairing.max_time_difference_s;
  if (options.rig) {
    head.cameras = 1 + options.rig->secondaries.size();
    head.reference_is_right = !options.rig->secondaries.empty() && options.rig->secondaries[0].bx < 0.0;
    head.mount = options.rig->pose_on_robot;
  }
  return head;
}

RosFrameAssembler::RosFrameAssembler(const RosHeadOptions& options)
    : options_(options),
      labels_(labelsInRigOrder(options)),
      images_(options.cameras),
      infos_(options.cameras),
      pairer_(ImagePairingOptions{labels_, options.max_time_difference_s}) {}

void RosFrameAssembler::addImage(size_t camera, const sensor_msgs::Image::ConstPtr& image) {
  if (camera >= options_.cameras) return;
  images_[camera].push_back(image);
  matchCameraMessages(camera);
}

void RosFrameAssembler::addCameraInfo(size_t camera, const sensor_msgs::CameraInfo::ConstPtr& info) {
  if (camera >= options_.cameras) return;
  infos_[camera].push_back(info);
  matchCameraMessages(camera);
}

void RosFrameAssembler::matchCameraMessages(size_t camera) {
  auto& images = images_[camera];
  auto& infos = infos_[camera];
  for (auto image = images.begin(); image != images.end();) {
    const auto info = std::find_if(infos.begin(), infos.end(), [&](const auto& candidate) {
      return candidate->header.stamp == (*image)->header.stamp;
    });
    if (info == infos.end()) {
      ++image;
      continue;
    }
    try {
      pairer_.add(toCameraObservation(**image, **info, kRosCameraNames[camera]));
    } catch (const ObservationRejected& rejection) {
      skipped_.add(rejection);
    }
    infos.erase(infos.begin(), info + 1);
    image = images.erase(images.begin(), image + 1);
  }
  // A camera driver publishes both for every capture; a few unmatched ones are messages lost in
  // transit, not worth keeping.
  constexpr size_t kMaxUnmatched = 30;
  while (images.size() > kMaxUnmatched) {
    skipped_.add(ObservationRejected(RejectReason::kMissingCalibration,
                                     std::string(kRosCameraNames[camera]) +
                                         ": an image without a CameraInfo of its stamp"));
    images.pop_front();
  }
  while (infos.size() > kMaxUnmatched) infos.pop_front();
  convertDecidedCaptures();
}

void RosFrameAssembler::addOdometry(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& pose) {
  odometry_.add(stamp, pose);
}

void RosFrameAssembler::finish() {
  pairer_.finish();
  convertDecidedCaptures();
  finished_ = true;
}

void RosFrameAssembler::convertDecidedCaptures() {
  while (auto capture = pairer_.next()) {
    try {
      if (!capture->missing.empty()) {
        throw ObservationRejected(RejectReason::kMissingPartner, capture->missing);
      }
      RigFrame frame = fromCameraImages(capture->images, "", rectifier_);
      frame.rig.pose_on_robot = options_.mount;
      frames_.push_back(std::move(frame));
    } catch (const ObservationRejected& rejection) {
      skipped_.add(rejection);
    }
  }
}

std::optional<RigFrame> RosFrameAssembler::next() {
  if (frames_.empty()) return std::nullopt;
  RigFrame& frame = frames_.front();
  if (options_.wait_for_odometry) {
    frame.odometry = odometry_.poseAt(frame.timestamp);
    if (!frame.odometry && !finished_) return std::nullopt;
    if (!frame.odometry) frame.odometry = odometry_.newest();
  }
  RigFrame ready = std::move(frame);
  frames_.pop_front();
  return ready;
}

}  // namespace stereonav
