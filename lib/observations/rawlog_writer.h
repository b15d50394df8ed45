#pragma once

#include <mrpt/io/CStream.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <optional>
#include <string>

#include "common/ini_section.h"
#include "observations/rig_frame.h"
#include "observations/rig_observations.h"

namespace stereonav {

// The two rawlog formats MRPT tools read
// (https://docs.mrpt.org/reference/latest/robotics_file_formats.html):
enum class RawlogLayout {
  // A flat sequence of observations; odometry as a CObservationOdometry labelled "ODOMETRY"
  // (absolute pose, the frame's timestamp) before the frame's camera observations.
  kObservations,
  // Alternating CActionCollection / CSensoryFrame; odometry as a CActionRobotMovement2D holding
  // the motion since the previous recorded odometry pose (the first: since the odometry origin),
  // so integrating the actions from (0,0,0) gives back every absolute pose. A frame without
  // odometry gets an empty CActionCollection.
  kSensoryFrames,
};

enum class ImageStorage {
  kEmbedded,  // pixels inside the rawlog
  kExternal,  // PNG files in "<rawlog stem>_Images" (see external_images.h)
};

struct RawlogWriterOptions {
  RawlogLayout layout = RawlogLayout::kObservations;
  ImageStorage image_storage = ImageStorage::kEmbedded;
  int compression_level = 1;              // gzip level 1-9; 0 writes a plain, uncompressed rawlog
  std::string sensor_label = "TRICLOPS";  // see rig_observations.h for the labels derived from it
};

// Keys (all optional, defaults above): layout = observations | sensory_frames,
// images = embedded | external, compression_level = 0..9, sensor_label.
RawlogWriterOptions loadRawlogWriterOptions(IniSection& section);

// Writes RigFrames to a rawlog as they come. The rawlog grows in a temporary file beside `path`
// that finish() renames to `path`, so an existing rawlog is only replaced by a complete one and a
// reader never sees a half-written object. External images are written straight into the images
// folder (each file atomically).
class RawlogWriter {
 public:
  // Throws std::runtime_error naming `path` if it cannot be created.
  RawlogWriter(std::string path, RawlogWriterOptions options);
  // Finishes (keeping every frame written so far) unless a write failed, in which case the
  // temporary file is removed and `path` left as it was.
  ~RawlogWriter();

  RawlogWriter(const RawlogWriter&) = delete;
  RawlogWriter& operator=(const RawlogWriter&) = delete;

  // Throws std::invalid_argument for a frame that does not match its rig (nothing is written
  // then) and std::runtime_error on I/O failure.
  void write(const RigFrame& frame);

  // Writes observations as recorded, e.g. a raw pair with its lens calibration from a dataset
  // converter, with the odometry of their instant if there is one. Throws std::runtime_error on
  // I/O failure.
  void write(RigObservations observations, const std::optional<mrpt::poses::CPose2D>& odometry);

  // Closes the rawlog and moves it into place. This is the path for saving partial work, e.g.
  // after Ctrl-C. Later calls do nothing; write() after finish() throws std::logic_error.
  void finish();

  size_t framesWritten() const { return frames_written_; }
  const std::string& sensorLabel() const { return options_.sensor_label; }

 private:
  void writeObject(const mrpt::serialization::CSerializable& object);

  std::string path_;
  std::string temporary_path_;
  std::string images_directory_;
  RawlogWriterOptions options_;
  std::unique_ptr<mrpt::io::CStream> stream_;
  bool failed_ = false;
  size_t frames_written_ = 0;
  mrpt::poses::CPose2D last_odometry_;  // the pose the next CActionRobotMovement2D starts from
};

}  // namespace stereonav
