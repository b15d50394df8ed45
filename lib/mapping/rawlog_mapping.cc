#include "mapping/rawlog_mapping.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "common/atomic_file.h"
#include "localization/tum_trajectory.h"
#include "mapping/debug_panel.h"
#include "mapping/frame_localizer.h"
#include "mapping/map_outputs.h"
#include "mapping/stereo_mapper.h"
#include "mapping/virtual_scan_recorder.h"

namespace stereonav {

std::vector<mrpt::poses::CPose2D> loadPoseList(const std::string& path) {
  std::vector<mrpt::poses::CPose2D> poses;
  for (const StampedPose& stamped : loadTrajectory(path)) poses.push_back(stamped.pose);
  return poses;
}

MapPoseSource parseMapPoseSource(const std::string& name) {
  if (name == "odometry") return MapPoseSource::kOdometry;
  if (name == "localized") return MapPoseSource::kLocalized;
  if (name == "ground_truth") return MapPoseSource::kGroundTruth;
  throw std::invalid_argument("pose source '" + name +
                              "': expected odometry, localized or ground_truth");
}

RawlogReaderOptions rawlogReaderOptions(const MappingOptions& options) {
  RawlogReaderOptions reader;
  reader.sensor_label = options.sensor_label;
  reader.expected_rig = options.rig;
  reader.pairing = options.pairing;
  reader.calibration = options.calibration;
  return reader;
}

size_t countRawlogFrames(const std::string& rawlog_path, const MappingOptions& options) {
  RawlogReader reader(rawlog_path, rawlogReaderOptions(options));
  size_t frames = 0;
  while (reader.next()) ++frames;
  return frames;
}

namespace {

// One replay of a rawlog: the state that lives from the first frame to the written outputs.
class RawlogMappingRun {
 public:
  RawlogMappingRun(const MappingOptions& options, const MappingJob& job, MappingReport& report)
      : options_(options), job_(job), run_options_(options), report_(report) {
    if (job.pose_source == MapPoseSource::kGroundTruth && job.ground_truth_poses.empty()) {
      throw std::invalid_argument("ground-truth poses asked for, but the pose list is empty");
    }
    // The localizer matches the virtual scans, so localized runs make them too.
    run_options_.mapper.virtual_scans = options.mapper.virtual_scans ||
                                        !job.virtual_scan_rawlog.empty() ||
                                        job.pose_source == MapPoseSource::kLocalized;
  }

  void map(const RigFrame& frame) {
    if (!mapper_) startWithRig(frame);
    if (frame.odometry) {
      odometry_ = *frame.odometry;
    } else {
      ++report_.frames_without_odometry;
    }
    mapper_->observe(frame);
    const mrpt::poses::CPose2D pose = poseOfFrame();
    mapper_->insertLastObservation(pose);
    report_.path.push_back(pose);
    trajectory_.push_back({mrpt::Clock::toDouble(frame.timestamp), pose});
    countPixels(mapper_->scanner());
    if (panels_ && (report_.path.size() - 1) % std::max<size_t>(job_.debug_panel_every, 1) == 0) {
      savePanel(pose);
    }
    if (!job_.virtual_scan_rawlog.empty()) virtual_scans_.add(*mapper_->virtualScan(), odometry_);
  }

  const mrpt::maps::CMetricMap& gridMap() const { return mapper_->map(); }

  void finish(const RawlogReader& reader, std::chrono::steady_clock::time_point start) {
    report_.frames_mapped = report_.path.size();
    report_.damage = reader.damage();
    report_.skipped = reader.skipped();
    if (pixels_ > 0.0) {
      report_.matched_pixel_fraction = matched_pixels_ / pixels_;
      report_.kept_pixel_fraction = kept_pixels_ / pixels_;
    }
    if (mapper_) report_.times = mapper_->times();
    outputs_.write([&] {
      saveMapOutputs(mapper_ ? mapper_->map() : *createGridMap(options_.grid),
                     options_.grid.stereo.update.scale, report_.path, job_.output_prefix);
    });
    if (!job_.virtual_scan_rawlog.empty()) {
      outputs_.write([&] { virtual_scans_.save(job_.virtual_scan_rawlog); });
    }
    outputs_.write([&] { saveTumTrajectory(job_.output_prefix + ".traj.tum", trajectory_); });
    report_.output_errors = outputs_.errors();
    report_.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outputs_.write([&] { writeStringAtomically(job_.output_prefix + ".stats.json", report_.toJson()); });
    outputs_.throwIfFailed();
  }

 private:
  // The mapper, localizer and panels are made for the first frame's rig.
  void startWithRig(const RigFrame& frame) {
    MergedCameraRig rig = mergeCameraRigs(options_.rig, frame.rig, options_.calibration_tolerance);
    report_.calibration_warnings = std::move(rig.warnings);
    mapper_ = std::make_unique<StereoMapper>(run_options_, rig.rig);
    if (job_.pose_source == MapPoseSource::kLocalized) {
      localizer_ = std::make_unique<FrameLocalizer>(options_.localization, rig.rig);
    }
    if (!job_.debug_panel_directory.empty()) {
      panels_ = std::make_unique<DebugPanelRenderer>(run_options_, rig.rig);
    }
  }

  mrpt::poses::CPose2D poseOfFrame() {
    switch (job_.pose_source) {
      case MapPoseSource::kOdometry:
        return odometry_;
      case MapPoseSource::kLocalized: {
        const ScanMatch& match = localizer_->update(
            odometry_, *mapper_, gridOfMap(mapper_->map(), options_.grid.stereo.update.scale));
        if (match.corrected) ++report_.frames_localized;
        report_.frames_floor_measured = localizer_->floorMeasuredSteps();
        return match.pose;
      }
      case MapPoseSource::kGroundTruth:
        break;
    }
    const size_t index = report_.path.size();
    if (index >= job_.ground_truth_poses.size()) {
      throw std::invalid_argument("the ground-truth pose list has " +
                                  std::to_string(job_.ground_truth_poses.size()) +
                                  " poses, the rawlog has more frames");
    }
    return job_.ground_truth_poses[index];
  }

  void countPixels(const DisparityScanner& scanner) {
    matched_pixels_ += static_cast<double>(scanner.matchedPixels());
    kept_pixels_ += static_cast<double>(scanner.keptPixels());
    pixels_ += static_cast<double>(scanner.disparity().total());
  }

  void savePanel(const mrpt::poses::CPose2D& pose) {
    const size_t index = report_.path.size() - 1;
    // A panel that cannot be written (a full disk) ends the panels, not the map.
    outputs_.write([&] {
      saveDebugPanel(panels_->render(mapper_->scanner(), index, pose), job_.debug_panel_directory, index);
    });
    if (outputs_.failed()) panels_.reset();
  }

  const MappingOptions& options_;
  const MappingJob& job_;
  MappingOptions run_options_;
  MappingReport& report_;
  std::unique_ptr<StereoMapper> mapper_;
  std::unique_ptr<DebugPanelRenderer> panels_;
  std::unique_ptr<FrameLocalizer> localizer_;
  std::vector<StampedPose> trajectory_;
  VirtualScanRecorder virtual_scans_;
  mrpt::poses::CPose2D odometry_;  // the last recorded; a frame without keeps it
  double matched_pixels_ = 0.0, kept_pixels_ = 0.0, pixels_ = 0.0;
  OutputBatch outputs_;
};

}  // namespace

MappingReport mapRawlog(const MappingOptions& options, const MappingJob& job,
                        const MappingCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  MappingReport report;
  report.rawlog_path = job.rawlog_path;
  RawlogMappingRun run(options, job, report);
  RawlogReader reader(job.rawlog_path, rawlogReaderOptions(options));
  while (auto frame = reader.next()) {
    run.map(*frame);
    if (callbacks.on_frame) callbacks.on_frame(report.path.size(), run.gridMap());
    if (callbacks.stop_requested && callbacks.stop_requested()) {
      report.interrupted = true;
      break;
    }
  }
  run.finish(reader, start);
  return report;
}

}  // namespace stereonav
