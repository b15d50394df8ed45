#include "occupancy_grid/ros_map.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/image_file.h"
#include "common/ini_section.h"

namespace stereonav {
namespace {

// The map_server YAML is flat "key: value" lines; a full YAML parser is not needed for it.
std::map<std::string, std::string> readYamlKeys(const std::string& path) {
  // A map YAML is a few lines: a device or a huge file named by mistake is refused, not read.
  constexpr std::uintmax_t kMaxYamlBytes = 1 << 20;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw std::runtime_error(path + ": no such map YAML file");
  if (std::filesystem::file_size(path, error) > kMaxYamlBytes) {
    throw std::runtime_error(path + ": larger than 1 MB, not a map_server YAML");
  }
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the map YAML");
  std::map<std::string, std::string> keys;
  std::string line;
  while (std::getline(in, line)) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    auto trim = [](std::string text) {
      const size_t first = text.find_first_not_of(" \t\r\"'");
      const size_t last = text.find_last_not_of(" \t\r\"'");
      return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
    };
    keys[trim(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }
  return keys;
}

// Map coordinates, resolutions and thresholds beyond this are damage, not maps.
constexpr double kMaxMapValue = 1e7;

double parseNumber(const std::string& path, const std::string& key, const std::string& text) {
  double value = 0.0;
  if (!parseFiniteDouble(text, value) || std::abs(value) > kMaxMapValue) {
    throw std::runtime_error(path + ": " + key + ": expected a number in " + describeRange(-kMaxMapValue, kMaxMapValue) +
                             ", got '" + text + "'");
  }
  return value;
}

std::string required(const std::map<std::string, std::string>& keys, const std::string& path,
                     const std::string& key) {
  const auto found = keys.find(key);
  if (found == keys.end() || found->second.empty()) throw std::runtime_error(path + ": missing key '" + key + "'");
  return found->second;
}

double optionalNumber(const std::map<std::string, std::string>& keys, const std::string& path,
                      const std::string& key, double fallback) {
  const auto found = keys.find(key);
  return found == keys.end() ? fallback : parseNumber(path, key, found->second);
}

}  // namespace

RosMap::RosMap(double resolution, double x_min, double y_min, cv::Mat1b classes)
    : resolution_(resolution), x_min_(x_min), y_min_(y_min), classes_(std::move(classes)) {}

CellClass RosMap::at(double x, double y) const {
  const double fx = std::floor((x - x_min_) / resolution_);
  const double fy = std::floor((y - y_min_) / resolution_);
  if (fx < 0 || fy < 0 || fx >= width() || fy >= height()) return CellClass::kUnknown;
  return cell(static_cast<int>(fx), static_cast<int>(fy));
}

RosMap loadRosMap(const std::string& yaml_path) {
  const std::map<std::string, std::string> keys = readYamlKeys(yaml_path);
  const double resolution = parseNumber(yaml_path, "resolution", required(keys, yaml_path, "resolution"));
  if (!(resolution >= 1e-4)) throw std::runtime_error(yaml_path + ": resolution: must be at least 1e-4 m");

  std::string origin = required(keys, yaml_path, "origin");
  for (char& c : origin) {
    if (c == '[' || c == ']' || c == ',') c = ' ';
  }
  std::istringstream origin_in(origin);
  std::string x_text, y_text, yaw_text, extra;
  double x_min = 0, y_min = 0, yaw = 0;
  if (!(origin_in >> x_text >> y_text >> yaw_text) || (origin_in >> extra) || !parseFiniteDouble(x_text, x_min) ||
      !parseFiniteDouble(y_text, y_min) || !parseFiniteDouble(yaw_text, yaw) || std::abs(x_min) > kMaxMapValue ||
      std::abs(y_min) > kMaxMapValue) {
    throw std::runtime_error(yaml_path + ": origin: expected [x, y, yaw], got '" + keys.at("origin") + "'");
  }
  if (yaw != 0.0) throw std::runtime_error(yaml_path + ": origin: a rotated map (yaw != 0) is not supported");

  const bool negate = optionalNumber(keys, yaml_path, "negate", 0.0) != 0.0;
  const double occupied_thresh = optionalNumber(keys, yaml_path, "occupied_thresh", 0.65);
  const double free_thresh = optionalNumber(keys, yaml_path, "free_thresh", 0.196);
  if (!(free_thresh <= occupied_thresh)) {
    throw std::runtime_error(yaml_path + ": free_thresh must not exceed occupied_thresh");
  }
  const auto mode = keys.find("mode");
  if (mode != keys.end() && mode->second != "trinary" && mode->second != "scale") {
    throw std::runtime_error(yaml_path + ": mode: '" + mode->second + "' is not supported (trinary | scale)");
  }

  std::string image_path = required(keys, yaml_path, "image");
  const size_t slash = yaml_path.find_last_of('/');
  if (image_path.front() != '/' && slash != std::string::npos) image_path = yaml_path.substr(0, slash + 1) + image_path;
  // map_server averages the colour channels; so does a greyscale read (within rounding).
  cv::Mat1b image;
  try {
    image = readImageFile(image_path, cv::IMREAD_GRAYSCALE);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(std::string(error.what()) + " (the map image of " + yaml_path + ")");
  }

  cv::Mat1b classes(image.size());
  for (int row = 0; row < image.rows; ++row) {
    const int iy = image.rows - 1 - row;  // the image's first row is the top of the map
    for (int x = 0; x < image.cols; ++x) {
      const double grey = image(row, x);
      const double occupancy = negate ? grey / 255.0 : (255.0 - grey) / 255.0;
      const CellClass value = occupancy > occupied_thresh ? CellClass::kOccupied
                              : occupancy < free_thresh   ? CellClass::kFree
                                                          : CellClass::kUnknown;
      classes(iy, x) = static_cast<uint8_t>(value);
    }
  }
  return RosMap(resolution, x_min, y_min, classes);
}

}  // namespace stereonav
