#include <unistd.h>

#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "observations/dataset_conversion.h"
#ifdef STEREONAV_WITH_ROS
#include "rosbag_convert.h"
#endif
#include "simulator/simulation_recorder.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav convert euroc|kitti --dataset DIR --out OUT.rawlog [--images external]\n"
    "       kitti only: [--camera-height M] [--distance-bias B] [--drift-deg-per-m D] [--seed S]\n"
    "Converts a public stereo dataset into a rawlog that 'stereonav map' (ini/euroc.ini,\n"
    "ini/kitti.ini), RawLogViewer and rawlog-edit read:\n"
    "  euroc  EuRoC MAV ASL folder (cam0/, cam1/ with data.csv, data/, sensor.yaml): the raw,\n"
    "         unrectified pair with its factory calibration (rectified when read), label EUROC\n"
    "  kitti  KITTI odometry (calib.txt, image_l|image_0/, image_r|image_1/, poses.txt): the\n"
    "         rectified pair, label KITTI, the camera level M metres (default 1.65) above the\n"
    "         road. poses.txt becomes the odometry, with a stated error as a wheeled base would\n"
    "         report it: every distance scaled by 1 + B (default 0) and the heading drifting by a\n"
    "         Gaussian of D degrees per metre (default 0; seeded by S, default 1); the true poses\n"
    "         are written as OUT.gt.txt ('t x y phi', for 'stereonav map --use-ground-truth-poses').\n"
    "       rosbag|to-rosbag --dataset IN --out OUT [--config INI] [--images external]\n"
    "  rosbag     a ROS 1 bag of a stereo head (stereo_image_proc's <ns>/left|right|top/image_rect\n"
    "             or image_raw + camera_info, nav_msgs/Odometry) into a rawlog; the head (cameras,\n"
    "             reference, mount, pairing tolerance) from the ini's [rig] and [rawlog]\n"
    "  to-rosbag  a rawlog (read as 'stereonav map' reads it with INI) into a bag of\n"
    "             /stereo/<camera>/image_rect + camera_info and /odom, for stereonav_node\n"
    "--images external writes the images as PNG files in OUT_Images/ (MRPT's external storage).\n";

struct KittiRequest {
  double camera_height_m = 1.65;
  OdometryError odometry_error;
};

KittiRequest parseKittiRequest(CommandLine& command_line) {
  KittiRequest request;
  request.camera_height_m = command_line.doubleValue("camera-height", 0.01, 100.0).value_or(1.65);
  request.odometry_error.distance_bias = command_line.doubleValue("distance-bias", -0.5, 0.5).value_or(0.0);
  request.odometry_error.drift_deg_per_m = command_line.doubleValue("drift-deg-per-m", 0.0, 90.0).value_or(0.0);
  request.odometry_error.seed = static_cast<unsigned>(command_line.intValue("seed").value_or(1));
  return request;
}

// Beside OUT.rawlog, OUT.gt.txt: 't x y phi' per frame, as the simulator's recordings have.
void saveKittiTruth(const KittiSequence& sequence, const std::string& rawlog_path) {
  std::ostringstream truth;
  truth << std::setprecision(9);
  for (size_t i = 0; i < sequence.poses.size(); ++i) {
    truth << i / 10.0 << ' ' << sequence.poses[i].x() << ' ' << sequence.poses[i].y() << ' '
          << sequence.poses[i].phi() << '\n';
  }
  writeStringAtomically(SimulationRecorder::groundTruthPath(rawlog_path), truth.str());
}

}  // namespace

int runConvertCommand(const std::vector<std::string>& arguments) {
  if (!arguments.empty() && (arguments[0] == "--help" || arguments[0] == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  const bool rosbag = !arguments.empty() && (arguments[0] == "rosbag" || arguments[0] == "to-rosbag");
  if (arguments.empty() || (arguments[0] != "euroc" && arguments[0] != "kitti" && !rosbag)) {
    throw UsageError("the first argument is the format: euroc, kitti, rosbag or to-rosbag");
  }
  const bool kitti = arguments[0] == "kitti";
  CommandLine command_line({arguments.begin() + 1, arguments.end()}, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  if (rosbag) {
#ifdef STEREONAV_WITH_ROS
    return runRosbagConversion(arguments[0], command_line);
#else
    throw UsageError(arguments[0] + ": this stereonav was built without ROS 1 (scripts/setup installs it)");
#endif
  }
  const std::string dataset = command_line.required("dataset");
  const std::string out = command_line.required("out");
  const std::string images = command_line.value("images").value_or("embedded");
  const std::optional<KittiRequest> kitti_request =
      kitti ? std::optional(parseKittiRequest(command_line)) : std::nullopt;
  command_line.rejectUnknown();
  if (images != "embedded" && images != "external") {
    throw UsageError("--images '" + images + "': expected embedded or external");
  }

  RawlogWriterOptions options;
  options.sensor_label = kitti ? "KITTI" : "EUROC";
  options.image_storage = images == "external" ? ImageStorage::kExternal : ImageStorage::kEmbedded;
  const std::optional<KittiSequence> sequence =
      kitti ? std::optional(loadKittiSequence(dataset, kitti_request->camera_height_m)) : std::nullopt;
  RawlogWriter writer(out, options);
  const bool interactive = isatty(STDERR_FILENO) != 0;
  const auto progress = [&](size_t frames) {
    if (interactive) std::cerr << "\rstereonav convert: " << frames << " frames" << std::flush;
  };
  const size_t frames = kitti ? convertKitti(*sequence, kitti_request->odometry_error, writer, progress)
                              : convertEuroc(dataset, writer, progress);
  writer.finish();
  if (interactive) std::cerr << "\n";
  const bool with_truth = kitti && !sequence->poses.empty();
  if (with_truth) saveKittiTruth(*sequence, out);
  std::cerr << "stereonav convert: wrote " << frames << " frames of " << dataset << " to " << out
            << (with_truth ? " and " + SimulationRecorder::groundTruthPath(out) : "") << "\n";
  return 0;
}

}  // namespace stereonav::app
