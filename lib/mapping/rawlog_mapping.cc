#include "mapping/rawlog_mapping.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "common/atomic_file.h"
#include "localization/scan_localizer.h"
#include "localization/tum_trajectory.h"
#include "mapping/debug_panel.h"
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

MappingReport mapRawlog(const MappingOptions& options, const MappingJob& job,
                        const MappingCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  MappingReport report;
  report.rawlog_path = job.rawlog_path;

  if (job.pose_source == MapPoseSource::kGroundTruth && job.ground_truth_poses.empty()) {
    throw std::invalid_argument("ground-truth poses asked for, but the pose list is empty");
  }
  MappingOptions run_options = options;
  run_options.mapper.virtual_scans = options.mapper.virtual_scans ||
                                     !job.virtual_scan_rawlog.empty() ||
                                     job.pose_source == MapPoseSource::kLocalized;
  RawlogReader reader(job.rawlog_path, rawlogReaderOptions(options));
  std::unique_ptr<StereoMapper> mapper;  // made for the first frame's rig
  std::unique_ptr<DebugPanelRenderer> panels;
  std::unique_ptr<ScanLocalizer> localizer;
  std::vector<StampedPose> trajectory;
  VirtualScanRecorder virtual_scans;
  std::vector<mrpt::poses::CPose2D>& path = report.path;
  mrpt::poses::CPose2D odometry;  // the last recorded; a frame without keeps it
  mrpt::poses::CPose2D pose;      // the one mapped with
  double matched_pixels = 0.0, kept_pixels = 0.0, pixels = 0.0;
  OutputBatch outputs;

  while (auto frame = reader.next()) {
    if (!mapper) {
      MergedCameraRig rig = mergeCameraRigs(options.rig, frame->rig, options.calibration_tolerance);
      report.calibration_warnings = std::move(rig.warnings);
      mapper = std::make_unique<StereoMapper>(run_options, rig.rig);
      if (job.pose_source == MapPoseSource::kLocalized) {
        localizer = std::make_unique<ScanLocalizer>(
            options.localization, rig.rig.reference.focal_px * rig.rig.baseline_m);
      }
      if (!job.debug_panel_directory.empty()) {
        panels = std::make_unique<DebugPanelRenderer>(run_options, rig.rig);
      }
    }
    if (frame->odometry) {
      odometry = *frame->odometry;
    } else {
      ++report.frames_without_odometry;
    }
    mapper->observe(*frame);
    switch (job.pose_source) {
      case MapPoseSource::kOdometry:
        pose = odometry;
        break;
      case MapPoseSource::kLocalized: {
        const ScanMatch& match = localizer->update(
            odometry, *mapper->virtualScan(), gridOfMap(mapper->map(), options.grid.stereo.update.scale));
        pose = match.pose;
        if (match.corrected) ++report.frames_localized;
        break;
      }
      case MapPoseSource::kGroundTruth:
        if (path.size() >= job.ground_truth_poses.size()) {
          throw std::invalid_argument("the ground-truth pose list has " +
                                      std::to_string(job.ground_truth_poses.size()) +
                                      " poses, the rawlog has more frames");
        }
        pose = job.ground_truth_poses[path.size()];
        break;
    }
    mapper->insertLastObservation(pose);
    path.push_back(pose);
    trajectory.push_back({mrpt::Clock::toDouble(frame->timestamp), pose});
    const DisparityScanner& scanner = mapper->scanner();
    matched_pixels += static_cast<double>(scanner.matchedPixels());
    kept_pixels += static_cast<double>(scanner.keptPixels());
    pixels += static_cast<double>(scanner.disparity().total());
    if (panels && (path.size() - 1) % std::max<size_t>(job.debug_panel_every, 1) == 0) {
      // A panel that cannot be written (a full disk) ends the panels, not the map.
      outputs.write([&] {
        saveDebugPanel(panels->render(scanner, path.size() - 1, pose), job.debug_panel_directory,
                       path.size() - 1);
      });
      if (outputs.failed()) panels.reset();
    }
    if (!job.virtual_scan_rawlog.empty()) virtual_scans.add(*mapper->virtualScan(), odometry);
    if (callbacks.on_frame) callbacks.on_frame(path.size(), mapper->map());
    if (callbacks.stop_requested && callbacks.stop_requested()) {
      report.interrupted = true;
      break;
    }
  }

  report.frames_mapped = path.size();
  report.damage = reader.damage();
  report.skipped = reader.skipped();
  if (pixels > 0.0) {
    report.matched_pixel_fraction = matched_pixels / pixels;
    report.kept_pixel_fraction = kept_pixels / pixels;
  }
  const OccupancyScale& scale = options.grid.stereo.update.scale;
  if (mapper) report.times = mapper->times();
  outputs.write([&] {
    saveMapOutputs(mapper ? mapper->map() : *createGridMap(options.grid), scale, path, job.output_prefix);
  });
  if (!job.virtual_scan_rawlog.empty()) outputs.write([&] { virtual_scans.save(job.virtual_scan_rawlog); });
  outputs.write([&] { saveTumTrajectory(job.output_prefix + ".traj.tum", trajectory); });
  report.output_errors = outputs.errors();
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outputs.write([&] { writeStringAtomically(job.output_prefix + ".stats.json", report.toJson()); });
  outputs.throwIfFailed();
  return report;
}

}  // namespace stereonav
