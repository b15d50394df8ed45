#include "observations/rawlog_reader.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "common/error_text.h"
#include "observations/deserialization_budget.h"
#include "observations/external_images.h"

namespace stereonav {
namespace {

constexpr const char* kReasonNames[kRejectReasonCount] = {
    "without calibration", "wrong image format", "not rectified", "image missing",
    "wrong number of cameras", "missing partner image"};

// The camera index k of "<pair_label>_CAM<k>", or 0 if `label` is not of that form.
size_t extraCameraIndex(const std::string& label, const std::string& pair_label) {
  const std::string prefix = pair_label + "_CAM";
  if (label.size() <= prefix.size() || label.compare(0, prefix.size(), prefix) != 0) return 0;
  const std::string digits = label.substr(prefix.size());
  if (digits.size() > 3 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return std::stoul(digits);
}

}  // namespace

std::string RawlogDamage::describe(const std::string& path) const {
  return path + ": damaged, reading stopped at object #" + std::to_string(object_index) +
         " (byte " + std::to_string(byte_offset) + " of the uncompressed stream): " + error;
}

void SkippedFrames::add(const ObservationRejected& rejection) {
  const auto reason = static_cast<size_t>(rejection.reason());
  if (count[reason]++ == 0) first_message[reason] = rejection.what();
}

size_t SkippedFrames::total() const {
  size_t sum = 0;
  for (const size_t n : count) sum += n;
  return sum;
}

std::string SkippedFrames::summary() const {
  if (total() == 0) return "";
  std::ostringstream text;
  text << "skipped " << total() << " of the rawlog's stereo frames:";
  const char* separator = " ";
  for (size_t reason = 0; reason < count.size(); ++reason) {
    if (count[reason] == 0) continue;
    text << separator << count[reason] << " " << kReasonNames[reason] << " (e.g. "
         << first_message[reason] << ")";
    separator = ", ";
  }
  return text.str();
}

RawlogReader::RawlogReader(const std::string& path, RawlogReaderOptions options)
    : path_(path),
      images_directory_(findExternalImagesDirectory(path)),
      options_(std::move(options)),
      archive_(stream_),
      rectifier_(options_.calibration) {
  if (!options_.pairing.labels.empty()) pairer_.emplace(options_.pairing);
  // CFileGZInputStream throws a multi-line MRPT report for a missing file; say it in one line.
  if (!std::filesystem::is_regular_file(path_))
    throw std::runtime_error(path_ + ": no such rawlog file");
  bool opened = false;
  try {
    opened = stream_.open(path_);
  } catch (const std::exception&) {
    // reported below, without MRPT's backtrace
  }
  if (!opened) throw std::runtime_error(path_ + ": cannot open rawlog");
  uncompressed_size_ = uncompressedSize(path_);
}

std::optional<RigFrame> RawlogReader::next() {
  if (auto frame = nextPairedFrame()) return frame;
  while (!finished_) {
    const uint64_t offset = stream_.getPosition();
    mrpt::serialization::CSerializable::Ptr object;
    try {
      const uint64_t remaining = uncompressed_size_ > offset ? uncompressed_size_ - offset : 0;
      DeserializationBudget budget(DeserializationBudget::forRemainingBytes(remaining));
      object = archive_.ReadObject();
    } catch (const std::bad_alloc&) {
      finished_ = true;
      damage_ = RawlogDamage{object_index_, offset, "a size it declares exceeds what is left of the file"};
      return std::nullopt;
    } catch (const std::exception& e) {
      finished_ = true;
      // Nothing at all left to read is the normal end; anything else is a damaged object.
      const bool clean_end = dynamic_cast<const mrpt::serialization::CExceptionEOF*>(&e) &&
                             stream_.getPosition() == offset;
      if (!clean_end) damage_ = RawlogDamage{object_index_, offset, oneLineMessage(e.what())};
      if (pairer_) pairer_->finish();
      return nextPairedFrame();
    }
    ++object_index_;
    if (auto frame = handleObject(object)) return frame;
    if (auto frame = nextPairedFrame()) return frame;
  }
  return std::nullopt;
}

std::optional<RigFrame> RawlogReader::nextPairedFrame() {
  if (!pairer_) return std::nullopt;
  while (auto capture = pairer_->next()) {
    try {
      if (!capture->missing.empty()) {
        throw ObservationRejected(RejectReason::kMissingPartner, capture->missing);
      }
      const std::string label = capture->images.front()->sensorLabel;
      return finishFrame(fromCameraImages(capture->images, images_directory_, rectifier_), label);
    } catch (const ObservationRejected& rejection) {
      skipped_.add(rejection);
    }
  }
  return std::nullopt;
}

std::optional<RigFrame> RawlogReader::handleObject(
    const mrpt::serialization::CSerializable::Ptr& object) {
  if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(object)) {
    integrateMovement(*actions);
    return std::nullopt;
  }
  if (auto sensory_frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
    // Inside a sensory frame order carries no meaning: gather the extra cameras first.
    std::optional<RigFrame> frame;
    for (const auto& observation : *sensory_frame) collect(observation);
    for (const auto& observation : *sensory_frame) {
      auto pair = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(observation);
      if (pair && !frame && !pairer_) frame = completeFrame(*pair);
    }
    return frame;
  }
  if (auto pair = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(object)) {
    return pairer_ ? std::nullopt : completeFrame(*pair);
  }
  if (auto observation = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
    collect(observation);
  }
  return std::nullopt;
}

void RawlogReader::collect(const mrpt::obs::CObservation::Ptr& observation) {
  if (auto image = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(observation)) {
    if (pairer_) {
      pairer_->add(image);
      return;
    }
    // A frame's cameras share its timestamp, so older ones can no longer be completed; dropping
    // them keeps memory bounded in logs full of other cameras' images.
    if (!pending_images_.empty() && pending_images_.front()->timestamp != image->timestamp) {
      pending_images_.clear();
    }
    pending_images_.push_back(image);
  } else if (auto odometry =
                 std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(observation)) {
    pending_odometry_ = odometry->odometry;
    if (pairer_) odometry_history_.emplace_back(odometry->timestamp, odometry->odometry);
  }
}

void RawlogReader::integrateMovement(const mrpt::obs::CActionCollection& actions) {
  pending_odometry_.reset();
  for (const auto& action : actions) {
    if (auto movement =
            std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(action.get_ptr())) {
      integrated_movement_ = integrated_movement_ + movement->poseChange->getMeanVal();
      pending_odometry_ = integrated_movement_;
      if (pairer_) odometry_history_.emplace_back(movement->timestamp, integrated_movement_);
    }
  }
}

std::optional<RigFrame> RawlogReader::completeFrame(
    const mrpt::obs::CObservationStereoImages& pair) {
  if (options_.sensor_label.empty()) options_.sensor_label = pair.sensorLabel;
  if (pair.sensorLabel != options_.sensor_label) return std::nullopt;

  std::vector<mrpt::obs::CObservationImage::Ptr> images;
  images.swap(pending_images_);
  std::optional<mrpt::poses::CPose2D> odometry;
  odometry.swap(pending_odometry_);
  try {
    std::map<size_t, mrpt::obs::CObservationImage::Ptr> extra_by_index;
    for (const auto& image : images) {
      const size_t index = extraCameraIndex(image->sensorLabel, pair.sensorLabel);
      if (index >= 2 && image->timestamp == pair.timestamp) extra_by_index[index] = image;
    }
    std::vector<mrpt::obs::CObservationImage::Ptr> extra_cameras;
    for (const auto& [index, image] : extra_by_index) {
      if (index != extra_cameras.size() + 2) {
        throw ObservationRejected(RejectReason::kWrongCameraCount,
                                  pair.sensorLabel + ": " + image->sensorLabel +
                                      " without the cameras numbered before it");
      }
      extra_cameras.push_back(image);
    }
    const auto& expected = options_.expected_rig;
    const PairReference unnamed_reference =
        expected && !expected->secondaries.empty() && expected->secondaries[0].bx < 0
            ? PairReference::kRight
            : PairReference::kLeft;
    RigFrame frame = fromRigObservations(pair, extra_cameras, images_directory_, unnamed_reference,
                                         rectifier_);
    frame.odometry = odometry;
    return finishFrame(std::move(frame), pair.sensorLabel);
  } catch (const ObservationRejected& rejection) {
    skipped_.add(rejection);
    return std::nullopt;
  }
}

RigFrame RawlogReader::finishFrame(RigFrame frame, const std::string& label) {
  const auto& expected = options_.expected_rig;
  if (expected) {
    if (frame.rig.secondaries.size() != expected->secondaries.size()) {
      throw ObservationRejected(RejectReason::kWrongCameraCount,
                                label + ": " + std::to_string(frame.rig.secondaries.size() + 1) +
                                    " cameras, expected " +
                                    std::to_string(expected->secondaries.size() + 1));
    }
    if (frame.rig.reference.width != expected->reference.width ||
        frame.rig.reference.height != expected->reference.height) {
      throw ObservationRejected(RejectReason::kWrongImageFormat,
                                label + ": images are " + std::to_string(frame.rig.reference.width) +
                                    "x" + std::to_string(frame.rig.reference.height) +
                                    ", expected " + std::to_string(expected->reference.width) +
                                    "x" + std::to_string(expected->reference.height));
    }
  } else {
    options_.expected_rig = frame.rig;
  }
  if (pairer_) {
    const auto latest = frame.timestamp + std::chrono::microseconds(static_cast<int64_t>(
                                              options_.pairing.max_time_difference_s * 1e6));
    while (!odometry_history_.empty() && odometry_history_.front().first <= latest) {
      frame.odometry = odometry_history_.front().second;
      odometry_history_.pop_front();
    }
  }
  return frame;
}

}  // namespace stereonav
