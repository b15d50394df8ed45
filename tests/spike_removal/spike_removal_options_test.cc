#include "spike_removal/spike_removal_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include "support/options_loading.h"

namespace stereonav {
namespace {

SpikeRemovalOptions load(const std::string& text) {
  return test_support::loadSectionText("spike_removal", text, loadSpikeRemovalOptions);
}

std::string errorOf(const std::string& text) {
  return test_support::configErrorOf([&] { load(text); });
}

TEST(SpikeRemovalOptionsTest, DefaultsToThePapersSegmentation) {
  const SpikeRemovalOptions options = load("");
  EXPECT_EQ(options.filter, SpikeFilterType::kSegmentation);
  EXPECT_EQ(options.segmentation.max_difference, 1.0f);
  EXPECT_EQ(options.segmentation.connectivity, 8);
}

TEST(SpikeRemovalOptionsTest, LoadsEveryKey) {
  const SpikeRemovalOptions options = load(
      "filter = erosion\nmax_difference = 2\nmin_region_pixels = 200\nconnectivity = 4\n"
      "median_kernel = 5\nerosion_kernel = 5\n");
  EXPECT_EQ(options.filter, SpikeFilterType::kErosion);
  EXPECT_EQ(options.segmentation.max_difference, 2.0f);
  EXPECT_EQ(options.segmentation.min_region_pixels, 200);
  EXPECT_EQ(options.segmentation.connectivity, 4);
  EXPECT_EQ(options.median_kernel, 5);
  EXPECT_EQ(options.erosion_kernel, 5);
  EXPECT_EQ(load("filter = median\n").filter, SpikeFilterType::kMedian);
  EXPECT_EQ(load("filter = none\n").filter, SpikeFilterType::kNone);
}

TEST(SpikeRemovalOptionsTest, BadValuesNameSectionAndKey) {
  EXPECT_EQ(errorOf("filter = gaussian\n"),
            "[spike_removal] filter: expected none, median, erosion or segmentation, got "
            "'gaussian'");
  EXPECT_EQ(errorOf("connectivity = 6\n"), "[spike_removal] connectivity: must be 4 or 8");
  EXPECT_NE(errorOf("median_kernel = 7\n").find("[spike_removal] median_kernel"),
            std::string::npos);
  EXPECT_NE(errorOf("erosion_kernel = 4\n").find("[spike_removal] erosion_kernel"),
            std::string::npos);
  EXPECT_NE(errorOf("min_region_pixels = 0\n").find("[spike_removal] min_region_pixels"),
            std::string::npos);
  EXPECT_NE(errorOf("max_difference = -1\n").find("[spike_removal] max_difference"),
            std::string::npos);
  EXPECT_NE(errorOf("min_region_pixel = 10\n").find("did you mean 'min_region_pixels'"),
            std::string::npos);
}

}  // namespace
}  // namespace stereonav
