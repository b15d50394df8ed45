#include "mapping/rawlog_mapping.h"

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <memory>
#include <vector>

#include "common/atomic_file.h"
#include "mapping/debug_panel.h"
#include "mapping/map_outputs.h"
#include "mapping/stereo_mapper.h"
#include "mapping/virtual_scan_recorder.h"

namespace stereonav {

std::vector<mrpt::poses::CPose2D> loadPoseList(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot read pose list");
  std::vector<mrpt::poses::CPose2D> poses;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    const size_t comment = line.find('#');
    if (comment != std::string::npos) line.erase(comment);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    double t, x, y, phi;
    std::string rest;
    if (!(fields >> t >> x >> y >> phi) || (fields >> rest)) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected 't x y phi'");
    }
    poses.emplace_back(x, y, phi);
  }
  return poses;
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

  MappingOptions run_options = options;
  run_options.mapper.virtual_scans = options.mapper.virtual_scans || !job.virtual_scan_rawlog.empty();
  RawlogReader reader(job.rawlog_path, rawlogReaderOptions(options));
  std::unique_ptr<StereoMapper> mapper;  // made for the first frame's rig
  std::unique_ptr<DebugPanelRenderer> panels;
  VirtualScanRecorder virtual_scans;
  std::vector<mrpt::poses::CPose2D> path;
  mrpt::poses::CPose2D odometry;  // the last recorded; a frame without keeps it
  mrpt::poses::CPose2D pose;      // the one mapped with
  double matched_pixels = 0.0, kept_pixels = 0.0, pixels = 0.0;

  while (auto frame = reader.next()) {
    if (!mapper) {
      MergedCameraRig rig = mergeCameraRigs(options.rig, frame->rig, options.calibration_tolerance);
      report.calibration_warnings = std::move(rig.warnings);
      mapper = std::make_unique<StereoMapper>(run_options, rig.rig);
      if (!job.debug_panel_directory.empty()) {
        panels = std::make_unique<DebugPanelRenderer>(run_options, rig.rig);
      }
    }
    if (frame->odometry) {
      odometry = *frame->odometry;
    } else {
      ++report.frames_without_odometry;
    }
    if (job.ground_truth_poses.empty()) {
      pose = odometry;
    } else if (path.size() < job.ground_truth_poses.size()) {
      pose = job.ground_truth_poses[path.size()];
    } else {
      throw std::invalid_argument("the ground-truth pose list has " +
                                  std::to_string(job.ground_truth_poses.size()) +
                                  " poses, the rawlog has more frames");
    }
    mapper->process(*frame, pose);
    path.push_back(pose);
    const DisparityScanner& scanner = mapper->scanner();
    matched_pixels += static_cast<double>(scanner.matchedPixels());
    kept_pixels += static_cast<double>(scanner.keptPixels());
    pixels += static_cast<double>(scanner.disparity().total());
    if (panels) {
      saveDebugPanel(panels->render(scanner, path.size() - 1, pose), job.debug_panel_directory,
                     path.size() - 1);
    }
    if (!job.virtual_scan_rawlog.empty()) virtual_scans.add(*mapper->virtualScan(), odometry);
    if (callbacks.on_frame) callbacks.on_frame(path.size());
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
  if (mapper) {
    report.times = mapper->times();
    saveMapOutputs(mapper->map(), scale, path, job.output_prefix);
  } else {
    saveMapOutputs(*createGridMap(options.grid), scale, path, job.output_prefix);
  }
  if (!job.virtual_scan_rawlog.empty()) virtual_scans.save(job.virtual_scan_rawlog);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeStringAtomically(job.output_prefix + ".stats.json", report.toJson());
  return report;
}

}  // namespace stereonav
