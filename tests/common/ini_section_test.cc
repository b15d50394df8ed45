#include "common/ini_section.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace stereonav {
namespace {

TEST(IniSectionTest, ReadsValuesAndDefaults) {
  mrpt::config::CConfigFileMemory config("[stereo]\nwindow = 9\nsubpixel = true\nthreshold = 0.25\n");
  IniSection section(config, "stereo");
  EXPECT_EQ(section.getInt("window", 7), 9);
  EXPECT_TRUE(section.getBool("subpixel", false));
  EXPECT_DOUBLE_EQ(section.getDouble("threshold", 1.0), 0.25);
  EXPECT_EQ(section.getInt("max_disparity", 32), 32);
  EXPECT_NO_THROW(section.rejectUnknownKeys());
}

TEST(IniSectionTest, UnknownKeyNamesTheNearestKnownKey) {
  mrpt::config::CConfigFileMemory config("[stereo]\nwindow = 9\nwindwo_size = 3\n");
  IniSection section(config, "stereo");
  section.getInt("window", 7);
  section.getInt("window_size", 7);
  try {
    section.rejectUnknownKeys();
    FAIL() << "an unknown key was accepted";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[stereo] unknown key 'windwo_size' (did you mean 'window_size'?)");
  }
}

TEST(IniSectionTest, MalformedNumbersAreReported) {
  mrpt::config::CConfigFileMemory config("[stereo]\nwindow = seven\nsubpixel = maybe\n");
  IniSection section(config, "stereo");
  EXPECT_THROW(section.getInt("window", 7), ConfigError);
  EXPECT_THROW(section.getBool("subpixel", false), ConfigError);
}

TEST(NearestKeyTest, PicksSmallestEditDistance) {
  EXPECT_EQ(nearestKey("max_disparty", {"max_disparity", "min_disparity", "window"}), "max_disparity");
  EXPECT_EQ(nearestKey("anything", {}), "");
}

}  // namespace
}  // namespace stereonav
