#pragma once

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <array>
#include <cstdint>
#include <deque>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "observations/camera_image_pairing.h"
#include "observations/frame_rectifier.h"
#include "observations/rig_frame.h"
#include "observations/rig_observations.h"

namespace stereonav {

struct RawlogReaderOptions {
  // The stereo pair to follow; "" follows the label of the first CObservationStereoImages found.
  // Observations of other sensors are ignored.
  std::string sensor_label;
  // The rig the caller expects (e.g. from the [rig] ini section): frames with another image size
  // or number of cameras are skipped, and when the rawlog does not name the pair's reference
  // camera (rawlogs we did not write) its first secondary's side decides it. Without it the first
  // frame read sets the expectation and an unnamed pair's reference is its left camera.
  std::optional<CameraRig> expected_rig;
  // With labels: the head is recorded as one CObservationImage per camera, grouped into frames by
  // time (camera_image_pairing.h); CObservationStereoImages are then ignored.
  ImagePairingOptions pairing;
  // Replaces the calibration recorded in the observations (cameras in rig order; for a pair, left
  // then right). Either way an unrectified head is rectified on the fly (frame_rectifier.h).
  std::optional<RigCalibration> calibration;
};

// Where a damaged rawlog stopped being readable.
struct RawlogDamage {
  size_t object_index = 0;   // of the first unreadable object, counting from 0
  uint64_t byte_offset = 0;  // where that object starts, in the uncompressed stream
  std::string error;         // what MRPT's deserializer said, in one line (oneLineMessage)

  std::string describe(const std::string& path) const;
};

// Stereo frames the reader could not use, by reason, for one summary at the end of a run.
struct SkippedFrames {
  std::array<size_t, kRejectReasonCount> count{};             // indexed by RejectReason
  std::array<std::string, kRejectReasonCount> first_message;  // the first of each, for the user

  void add(const ObservationRejected& rejection);
  size_t total() const;
  // E.g. "skipped 2 of the rawlog's stereo frames: 2 wrong image format (TRICLOPS left: image is
  // 32x48, its camera is 64x48)"; "" if none was skipped.
  std::string summary() const;
};

// Reads a rawlog (either layout, gzip-compressed or not, images embedded or external) one
// RigFrame at a time, object by object, so a mapper can work on a long log frame by frame and so
// that damage loses only what follows it.
//
// A frame is the extra cameras' CObservationImage (labelled <label>_CAM<k>, same timestamp)
// followed by the pair's CObservationStereoImages, which completes it (rig_observations.h), or
// the images of the options' pairing labels grouped by time, with
// the odometry pose recorded since the previous frame: the latest CObservationOdometry, or the
// movement actions before the CSensoryFrame integrated from the odometry origin.
//
//   RawlogReader reader(path, options);
//   while (auto frame = reader.next()) process(*frame);
//   if (reader.damage()) warn(reader.damage()->describe(path));
//   if (reader.skipped().total()) warn(reader.skipped().summary());
class RawlogReader {
 public:
  // Throws std::runtime_error naming `path` if it cannot be opened.
  RawlogReader(const std::string& path, RawlogReaderOptions options);

  RawlogReader(const RawlogReader&) = delete;
  RawlogReader& operator=(const RawlogReader&) = delete;

  // The next usable frame, or nothing at the end of the rawlog or at the first unreadable object
  // (see damage()). A truncated last object counts as damage.
  std::optional<RigFrame> next();

  const std::optional<RawlogDamage>& damage() const { return damage_; }
  const SkippedFrames& skipped() const { return skipped_; }

 private:
  // Returns the frame completed by `pair`, if it is ours and usable.
  std::optional<RigFrame> handleObject(const mrpt::serialization::CSerializable::Ptr& object);
  void collect(const mrpt::obs::CObservation::Ptr& observation);
  void integrateMovement(const mrpt::obs::CActionCollection& actions);
  // The frame completed by `pair`, if it is ours and usable.
  std::optional<RigFrame> completeFrame(const mrpt::obs::CObservationStereoImages& pair);
  // The next paired capture that makes a usable frame, skipping (and counting) the others.
  std::optional<RigFrame> nextPairedFrame();
  // Checks a frame against the expected rig and gives it the odometry since the last frame.
  RigFrame finishFrame(RigFrame frame, const std::string& label);

  std::string path_;
  std::string images_directory_;
  RawlogReaderOptions options_;
  mrpt::io::CFileGZInputStream stream_;
  mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream> archive_;
  size_t object_index_ = 0;
  uint64_t uncompressed_size_ = 0;  // bounds what a record may declare (DeserializationBudget)
  bool finished_ = false;
  std::optional<RawlogDamage> damage_;
  SkippedFrames skipped_;
  FrameRectifier rectifier_;
  std::optional<CameraImagePairer> pairer_;

  // What has arrived since the last frame: the extra cameras of the newest timestamp seen, and
  // the odometry.
  std::vector<mrpt::obs::CObservationImage::Ptr> pending_images_;
  std::optional<mrpt::poses::CPose2D> pending_odometry_;
  // Paired captures are decided after later images (and odometry) have arrived: the odometry
  // recorded since the last frame, by time, to give each the pose of its own instant.
  std::deque<std::pair<mrpt::system::TTimeStamp, mrpt::poses::CPose2D>> odometry_history_;
  mrpt::poses::CPose2D integrated_movement_;  // sum of CActionRobotMovement2D so far
};

}  // namespace stereonav
