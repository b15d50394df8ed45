#include <mrpt/core/bits_math.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "observations/kitti_sequence.h"
#include "observations/rawlog_writer.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav import-kitti --sequence DIR --out OUT.rawlog [--camera-height M]\n"
    "                              [--distance-bias B] [--drift-deg-per-m D] [--seed S]\n"
    "Converts a KITTI odometry sequence (DIR/image_l, image_r, calib.txt, poses.txt) into a\n"
    "rawlog of binocular frames (reference = left camera; images stored externally in\n"
    "OUT_Images) with odometry, and writes the true poses as OUT.gt.txt ('t x y phi', 10 Hz).\n"
    "The odometry is the true motion with a stated error, as a wheeled base would report it:\n"
    "every distance scaled by 1 + B (default 0) and the heading drifting by a Gaussian of D\n"
    "degrees per metre (default 0; seeded by S, default 1). The camera is level, M metres\n"
    "(default 1.65) above the road.\n";

}  // namespace

int runImportKittiCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string directory = command_line.required("sequence");
  const std::string out = command_line.required("out");
  const double camera_height = command_line.doubleValue("camera-height").value_or(1.65);
  const double distance_bias = command_line.doubleValue("distance-bias").value_or(0.0);
  const double drift_deg_per_m = command_line.doubleValue("drift-deg-per-m").value_or(0.0);
  const int seed = command_line.intValue("seed").value_or(1);
  command_line.rejectUnknown();
  if (!(camera_height > 0.0)) throw UsageError("--camera-height: must be > 0 metres");
  if (!(drift_deg_per_m >= 0.0)) throw UsageError("--drift-deg-per-m: must be >= 0");

  const KittiSequence sequence = loadKittiSequence(directory, camera_height);
  RawlogWriterOptions options;
  options.image_storage = ImageStorage::kExternal;
  options.sensor_label = "KITTI";
  RawlogWriter writer(out, options);
  std::mt19937 random(static_cast<std::mt19937::result_type>(seed));
  std::normal_distribution<double> unit(0.0, 1.0);
  std::ostringstream truth;
  truth << "# t x y phi: true poses of " << directory << " (left camera on the floor)\n"
        << std::setprecision(9);
  mrpt::poses::CPose2D odometry = sequence.poses.front();
  for (size_t i = 0; i < sequence.poses.size(); ++i) {
    if (i > 0) {
      const mrpt::poses::CPose2D step = sequence.poses[i] - sequence.poses[i - 1];
      const double distance = step.norm();
      odometry = odometry + mrpt::poses::CPose2D(
                                step.x() * (1.0 + distance_bias), step.y() * (1.0 + distance_bias),
                                step.phi() + mrpt::DEG2RAD(drift_deg_per_m) * distance * unit(random));
    }
    writer.write(kittiFrame(sequence, i, odometry));
    truth << i / 10.0 << ' ' << sequence.poses[i].x() << ' ' << sequence.poses[i].y() << ' '
          << sequence.poses[i].phi() << '\n';
    std::cerr << "\rimport-kitti: frame " << i + 1 << "/" << sequence.poses.size() << std::flush;
  }
  writer.finish();
  const std::string stem = out.size() > 7 && out.substr(out.size() - 7) == ".rawlog"
                               ? out.substr(0, out.size() - 7) : out;
  writeStringAtomically(stem + ".gt.txt", truth.str());
  std::cerr << "\nimport-kitti: wrote " << out << " and " << stem << ".gt.txt\n";
  return 0;
}

}  // namespace stereonav::app
