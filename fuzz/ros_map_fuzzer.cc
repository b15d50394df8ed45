// libFuzzer target: the ROS map_server reader. The input is the YAML text, then (after the first
// NUL byte, if any) the bytes of the image it names, "map.pgm".
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "occupancy_grid/ros_map.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto* split = static_cast<const uint8_t*>(std::memchr(data, 0, size));
  const size_t yaml_size = split ? static_cast<size_t>(split - data) : size;
  stereonav::fuzz::FuzzInputFile image(split ? split + 1 : data, split ? size - yaml_size - 1 : 0, ".pgm");
  std::string yaml(reinterpret_cast<const char*>(data), yaml_size);
  const std::string image_name = image.path().substr(image.path().find_last_of('/') + 1);
  for (size_t at = yaml.find("map.pgm"); at != std::string::npos; at = yaml.find("map.pgm", at + 1)) {
    yaml.replace(at, 7, image_name);
  }
  stereonav::fuzz::FuzzInputFile file(reinterpret_cast<const uint8_t*>(yaml.data()), yaml.size(), ".yaml");
  try {
    stereonav::loadRosMap(file.path());
  } catch (const std::runtime_error&) {
  }
  return 0;
}
