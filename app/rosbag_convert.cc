#include <unistd.h>

#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "mapping/mapping_options.h"
#include "mapping/rawlog_mapping.h"
#include "rosbag_convert.h"
#include "ros_bridge/rosbag_conversion.h"

namespace stereonav::app {

int runRosbagConversion(const std::string& direction, CommandLine& command_line) {
  const std::string input = command_line.required("dataset");
  const std::string out = command_line.required("out");
  const std::optional<std::string> config = command_line.value("config");
  const std::string images = command_line.value("images").value_or("embedded");
  command_line.rejectUnknown();
  if (images != "embedded" && images != "external") {
    throw UsageError("--images '" + images + "': expected embedded or external");
  }
  const MappingOptions options = config ? loadMappingOptionsFile(*config) : MappingOptions{};
  const bool interactive = isatty(STDERR_FILENO) != 0;
  const auto progress = [&](size_t frames) {
    if (interactive) std::cerr << "\rstereonav convert: " << frames << " frames" << std::flush;
  };
  if (direction == "to-rosbag") {
    const size_t frames = writeRosbagFromRawlog(input, rawlogReaderOptions(options), out, progress);
    if (interactive) std::cerr << "\n";
    std::cerr << "stereonav convert: wrote " << frames << " frames of " << input << " to " << out << "\n";
    return 0;
  }
  RawlogWriterOptions writer_options;
  writer_options.sensor_label = options.sensor_label.empty() ? "STEREO" : options.sensor_label;
  writer_options.image_storage = images == "external" ? ImageStorage::kExternal : ImageStorage::kEmbedded;
  RawlogWriter writer(out, writer_options);
  const RosbagConversionReport report = convertRosbagToRawlog(input, rosHeadOptions(options), writer, progress);
  writer.finish();
  if (interactive) std::cerr << "\n";
  std::cerr << "stereonav convert: wrote " << report.frames << " frames of " << input << " ("
            << report.image_topics << ", " << report.odometry_messages << " odometry messages) to "
            << out << "\n";
  if (report.skipped.total() > 0) std::cerr << "stereonav convert: " << report.skipped.summary() << "\n";
  if (!report.damage.empty()) {
    std::cerr << "stereonav convert: " << report.damage << "\n";
    return kPartialWorkStatus;
  }
  return 0;
}

}  // namespace stereonav::app
