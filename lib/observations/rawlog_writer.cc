#include "observations/rawlog_writer.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "observations/external_images.h"
#include "observations/rig_observations.h"

namespace stereonav {
namespace {

// "dir/run.rawlog" -> "dir/run.tmp<pid>.rawlog": same folder (rename stays atomic), and the
// same naming as writeFileAtomically so one pattern of leftovers exists after a crash.
std::string temporaryPathFor(const std::string& path) {
  const std::filesystem::path target(path);
  return (target.parent_path() / (target.stem().string() + ".tmp" + std::to_string(::getpid()) +
                                  target.extension().string()))
      .string();
}

std::string frameNumber(size_t index) {
  char text[16];
  std::snprintf(text, sizeof text, "%06zu", index);
  return text;
}

}  // namespace

RawlogWriterOptions loadRawlogWriterOptions(IniSection& section) {
  RawlogWriterOptions options;
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section.name() + "] " + key + ": " + why);
  };
  const std::string layout = section.getString("layout", "observations");
  if (layout == "observations") {
    options.layout = RawlogLayout::kObservations;
  } else if (layout == "sensory_frames") {
    options.layout = RawlogLayout::kSensoryFrames;
  } else {
    fail("layout", "expected observations or sensory_frames, got '" + layout + "'");
  }
  const std::string images = section.getString("images", "embedded");
  if (images == "embedded") {
    options.image_storage = ImageStorage::kEmbedded;
  } else if (images == "external") {
    options.image_storage = ImageStorage::kExternal;
  } else {
    fail("images", "expected embedded or external, got '" + images + "'");
  }
  options.compression_level = section.getInt("compression_level", options.compression_level, 0, 9);
  options.sensor_label = section.getString("sensor_label", options.sensor_label);
  if (options.sensor_label.empty()) fail("sensor_label", "must not be empty");
  return options;
}

RawlogWriter::RawlogWriter(std::string path, RawlogWriterOptions options)
    : path_(std::move(path)),
      temporary_path_(temporaryPathFor(path_)),
      images_directory_(externalImagesDirectoryFor(path_)),
      options_(std::move(options)) {
  if (options_.image_storage == ImageStorage::kExternal) {
    std::error_code error;
    std::filesystem::create_directories(images_directory_, error);
    if (error)
      throw std::runtime_error(images_directory_ + ": cannot create (" + error.message() + ")");
  }
  if (options_.compression_level == 0) {
    auto plain = std::make_unique<mrpt::io::CFileOutputStream>();
    if (plain->open(temporary_path_, mrpt::io::OpenMode::TRUNCATE)) stream_ = std::move(plain);
  } else {
    auto gz = std::make_unique<mrpt::io::CFileGZOutputStream>();
    if (gz->open(temporary_path_, options_.compression_level)) stream_ = std::move(gz);
  }
  if (!stream_) throw std::runtime_error(path_ + ": cannot create rawlog");
}

RawlogWriter::~RawlogWriter() {
  if (!stream_) return;
  if (failed_) {
    stream_.reset();
    std::remove(temporary_path_.c_str());
    return;
  }
  try {
    finish();
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
  }
}

void RawlogWriter::writeObject(const mrpt::serialization::CSerializable& object) {
  try {
    auto archive = mrpt::serialization::archiveFrom(*stream_);
    archive << object;
  } catch (const std::exception& e) {
    failed_ = true;
    throw std::runtime_error(path_ + ": write failed (" + e.what() + ")");
  }
}

void RawlogWriter::write(const RigFrame& frame) {
  if (!stream_) throw std::logic_error(path_ + ": write() after finish()");
  write(toRigObservations(frame, options_.sensor_label), frame.odometry);
}

void RawlogWriter::write(RigObservations observations,
                         const std::optional<mrpt::poses::CPose2D>& odometry) {
  if (!stream_) throw std::logic_error(path_ + ": write() after finish()");
  const mrpt::system::TTimeStamp timestamp = observations.pair->timestamp;
  if (options_.image_storage == ImageStorage::kExternal) {
    const std::string number = frameNumber(frames_written_);
    auto& pair = *observations.pair;
    storeImageExternally(pair.imageLeft, images_directory_,
                         options_.sensor_label + "_" + number + "_left.png");
    storeImageExternally(pair.imageRight, images_directory_,
                         options_.sensor_label + "_" + number + "_right.png");
    for (auto& extra : observations.extra_cameras) {
      storeImageExternally(extra->image, images_directory_,
                           extra->sensorLabel + "_" + number + ".png");
    }
  }

  // The pair goes last: it completes the frame for a streaming reader (see rawlog_reader.h).
  if (options_.layout == RawlogLayout::kObservations) {
    if (odometry) {
      mrpt::obs::CObservationOdometry recorded;
      recorded.timestamp = timestamp;
      recorded.sensorLabel = "ODOMETRY";
      recorded.odometry = *odometry;
      writeObject(recorded);
    }
    for (const auto& extra : observations.extra_cameras) writeObject(*extra);
    writeObject(*observations.pair);
  } else {
    mrpt::obs::CActionCollection actions;
    if (odometry) {
      mrpt::obs::CActionRobotMovement2D movement;
      movement.timestamp = timestamp;
      movement.computeFromOdometry(*odometry - last_odometry_, {});
      actions.insert(movement);
      last_odometry_ = *odometry;
    }
    mrpt::obs::CSensoryFrame observations_frame;
    for (const auto& extra : observations.extra_cameras) observations_frame.insert(extra);
    observations_frame.insert(observations.pair);
    writeObject(actions);
    writeObject(observations_frame);
  }
  ++frames_written_;
}

void RawlogWriter::finish() {
  if (!stream_) return;
  stream_.reset();  // closes (and for gzip, completes) the file
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    std::remove(temporary_path_.c_str());
    throw std::runtime_error(path_ + ": cannot write (rename of the temporary file failed)");
  }
}

}  // namespace stereonav
