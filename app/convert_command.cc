#include <unistd.h>

#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "observations/dataset_conversion.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav convert euroc|kitti --dataset DIR --out OUT.rawlog [--images external]\n"
    "Converts a public stereo dataset into a rawlog that 'stereonav map' (ini/euroc.ini,\n"
    "ini/kitti.ini), RawLogViewer and rawlog-edit read:\n"
    "  euroc  EuRoC MAV ASL folder (cam0/, cam1/ with data.csv, data/, sensor.yaml): the raw,\n"
    "         unrectified pair with its factory calibration (rectified when read), label EUROC\n"
    "  kitti  KITTI odometry (calib.txt, image_l|image_0/, image_r|image_1/, poses.txt): the\n"
    "         rectified pair, poses.txt as odometry, label KITTI\n"
    "--images external writes the images as PNG files in OUT_Images/ (MRPT's external storage).\n";

}  // namespace

int runConvertCommand(const std::vector<std::string>& arguments) {
  if (!arguments.empty() && (arguments[0] == "--help" || arguments[0] == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  if (arguments.empty() || (arguments[0] != "euroc" && arguments[0] != "kitti")) {
    throw UsageError("the first argument is the dataset format: euroc or kitti");
  }
  const std::string format = arguments[0];
  CommandLine command_line({arguments.begin() + 1, arguments.end()}, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string dataset = command_line.required("dataset");
  const std::string out = command_line.required("out");
  const std::string images = command_line.value("images").value_or("embedded");
  command_line.rejectUnknown();
  if (images != "embedded" && images != "external") {
    throw UsageError("--images '" + images + "': expected embedded or external");
  }

  RawlogWriterOptions options;
  options.sensor_label = format == "euroc" ? "EUROC" : "KITTI";
  options.image_storage = images == "external" ? ImageStorage::kExternal : ImageStorage::kEmbedded;
  RawlogWriter writer(out, options);
  const bool interactive = isatty(STDERR_FILENO) != 0;
  const auto progress = [&](size_t frames) {
    if (interactive) std::cerr << "\rstereonav convert: " << frames << " frames" << std::flush;
  };
  const size_t frames = format == "euroc" ? convertEuroc(dataset, writer, progress)
                                          : convertKitti(dataset, writer, progress);
  writer.finish();
  if (interactive) std::cerr << "\n";
  std::cerr << "stereonav convert: wrote " << frames << " frames of " << dataset << " to " << out
            << "\n";
  return 0;
}

}  // namespace stereonav::app
