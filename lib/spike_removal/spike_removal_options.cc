#include "spike_removal/spike_removal_options.h"

namespace stereonav {
namespace {

constexpr SpikeFilterType kAllFilters[] = {SpikeFilterType::kNone, SpikeFilterType::kMedian,
                                           SpikeFilterType::kErosion,
                                           SpikeFilterType::kSegmentation};

}  // namespace

std::string spikeFilterName(SpikeFilterType type) {
  switch (type) {
    case SpikeFilterType::kNone:
      return "none";
    case SpikeFilterType::kMedian:
      return "median";
    case SpikeFilterType::kErosion:
      return "erosion";
    case SpikeFilterType::kSegmentation:
      return "segmentation";
  }
  return "";
}

SpikeRemovalOptions loadSpikeRemovalOptions(IniSection& section) {
  SpikeRemovalOptions options;
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section.name() + "] " + key + ": " + why);
  };

  const std::string filter = section.getString("filter", spikeFilterName(options.filter));
  bool known_filter = false;
  for (const SpikeFilterType type : kAllFilters) {
    if (filter == spikeFilterName(type)) {
      options.filter = type;
      known_filter = true;
    }
  }
  if (!known_filter) {
    fail("filter", "expected none, median, erosion or segmentation, got '" + filter + "'");
  }

  auto& segmentation = options.segmentation;
  segmentation.max_difference = static_cast<float>(
      section.getDouble("max_difference", segmentation.max_difference, 0.0, 1e4));
  segmentation.min_region_pixels =
      section.getInt("min_region_pixels", segmentation.min_region_pixels, 1, 1 << 24);
  segmentation.connectivity = section.getInt("connectivity", segmentation.connectivity);
  options.median_kernel = section.getInt("median_kernel", options.median_kernel);
  options.erosion_kernel = section.getInt("erosion_kernel", options.erosion_kernel, 3, 255);

  if (!(segmentation.max_difference >= 0.0f)) fail("max_difference", "must be >= 0");
  if (segmentation.min_region_pixels < 1) fail("min_region_pixels", "must be >= 1");
  if (segmentation.connectivity != 4 && segmentation.connectivity != 8) {
    fail("connectivity", "must be 4 or 8");
  }
  if (options.median_kernel != 3 && options.median_kernel != 5) {
    fail("median_kernel", "must be 3 or 5 (cv::medianBlur on float images)");
  }
  if (options.erosion_kernel < 3 || options.erosion_kernel % 2 == 0) {
    fail("erosion_kernel", "must be odd and >= 3");
  }
  return options;
}

}  // namespace stereonav
