#pragma once

#include <string>

#include "common/ini_section.h"

namespace stereonav {

// Which filter removes stereo mismatches ("spikes") from the disparity image. Paper section 4.1
// compares median and morphological filtering with the surface segmentation of section 4.2.
enum class SpikeFilterType { kNone, kMedian, kErosion, kSegmentation };

// Surface segmentation (paper section 4.2): neighbouring valid pixels whose disparities differ by
// at most max_difference belong to the same surface; surfaces of fewer than min_region_pixels
// pixels are invalidated.
struct SurfaceSegmentationOptions {
  float max_difference = 1.0f;  // pixels of disparity; the paper uses |d_j - d_i| <= 1
  int min_region_pixels = 50;
  int connectivity = 8;  // 4 or 8
};

struct SpikeRemovalOptions {
  SpikeFilterType filter = SpikeFilterType::kSegmentation;
  SurfaceSegmentationOptions segmentation;
  int median_kernel = 3;   // 3 or 5 (cv::medianBlur handles float images only up to 5)
  int erosion_kernel = 3;  // odd, >= 3
};

// Section [spike_removal]. Keys: filter = none|median|erosion|segmentation, max_difference,
// min_region_pixels, connectivity, median_kernel, erosion_kernel. Throws ConfigError on bad values.
SpikeRemovalOptions loadSpikeRemovalOptions(IniSection& section);

std::string spikeFilterName(SpikeFilterType type);

}  // namespace stereonav
