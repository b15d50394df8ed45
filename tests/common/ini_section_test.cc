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

TEST(IniSectionTest, SignChecksNameTheKey) {
  mrpt::config::CConfigFileMemory config("[robot]\nradius_m = 0\nmargin_m = -0.1\nspeed = 1.5\n");
  IniSection section(config, "robot");
  EXPECT_DOUBLE_EQ(section.getPositive("speed", 1.0), 1.5);
  EXPECT_DOUBLE_EQ(section.getNonNegative("radius_m", 1.0), 0.0);
  try {
    section.getPositive("radius_m", 1.0);
    FAIL() << "zero accepted as positive";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[robot] radius_m: must be positive");
  }
  EXPECT_THROW(section.getNonNegative("margin_m", 0.0), ConfigError);
}

TEST(LoadIniSectionTest, RejectsKeysTheLoaderDidNotRead) {
  mrpt::config::CConfigFileMemory config("[robot]\nspeed = 2\n[typo]\nsped = 2\n");
  const auto load = [](IniSection& section) { return section.getDouble("speed", 1.0); };
  EXPECT_DOUBLE_EQ(loadIniSection(config, "robot", load), 2.0);
  EXPECT_THROW(loadIniSection(config, "typo", load), ConfigError);
}

TEST(NearestKeyTest, PicksSmallestEditDistance) {
  EXPECT_EQ(nearestKey("max_disparty", {"max_disparity", "min_disparity", "window"}), "max_disparity");
  EXPECT_EQ(nearestKey("anything", {}), "");
}

}  // namespace
}  // namespace stereonav
