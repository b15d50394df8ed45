#include "common/ini_section.h"
#include "common/ini_key_recorder.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace stereonav {
namespace {

TEST(ConfigFileTest, TextMrptCannotParseIsOneLineNamingTheFile) {
  try {
    parseConfigText("[grid]\nresolution = $eval{0.1 * \n", "bad.ini");
    FAIL() << "parsed";
  } catch (const ConfigError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("bad.ini: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("===="), std::string::npos) << message;
  }
  EXPECT_DOUBLE_EQ(parseConfigText("[grid]\nresolution = $eval{0.1 * 2}\n", "good.ini")
                       .read_double("grid", "resolution", 0.0),
                   0.2);
}

TEST(ConfigFileTest, AMissingFileIsNamed) {
  try {
    readConfigFile("/nonexistent/stereonav.ini");
    FAIL() << "read";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/stereonav.ini"), std::string::npos);
  }
}

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
    EXPECT_STREQ(error.what(), "[robot] radius_m: must be positive, got '0'");
  }
  EXPECT_THROW(section.getNonNegative("margin_m", 0.0), ConfigError);
}

TEST(IniSectionTest, WholeValueMustBeOneFiniteNumber) {
  // B15: "1,5" used to be read as 1.
  for (const char* bad : {"1,5", "0.1abc", "0.1 0.2", "nan", "NaN", "inf", "-inf", "1e999", "0x", "", "--1"}) {
    mrpt::config::CConfigFileMemory config(std::string("[grid]\nresolution = ") + bad + "\n");
    IniSection section(config, "grid");
    EXPECT_THROW(section.getDouble("resolution", 0.05), ConfigError) << "'" << bad << "'";
  }
  mrpt::config::CConfigFileMemory config("[grid]\nresolution = 1.5e-1\n");
  IniSection section(config, "grid");
  EXPECT_DOUBLE_EQ(section.getDouble("resolution", 0.05), 0.15);
}

TEST(IniSectionTest, RangeErrorNamesSectionKeyRangeAndValue) {
  mrpt::config::CConfigFileMemory config("[grid]\nresolution = 1e-7\nmax_cells = 99999999999\nwindow = 7\n");
  IniSection section(config, "grid");
  try {
    section.getDouble("resolution", 0.05, 1e-3, 100.0);
    FAIL() << "out of range accepted";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[grid] resolution: expected [0.001, 100], got '1e-7'");
  }
  try {
    section.getInt("max_cells", 1, 1, 1000);
    FAIL() << "an integer beyond int accepted";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[grid] max_cells: expected an integer in 1..1000, got '99999999999'");
  }
  EXPECT_EQ(section.getInt("window", 3, 3, 7), 7);  // bounds are inclusive
  EXPECT_THROW(section.getInt("window", 3, 3, 6), ConfigError);
}

TEST(IniSectionTest, DefaultsAreNotRangeChecked) {
  mrpt::config::CConfigFileMemory config("[grid]\n");
  IniSection section(config, "grid");
  EXPECT_DOUBLE_EQ(section.getDouble("resolution", 0.05, 1.0, 2.0), 0.05);
}

TEST(ParseNumberTest, StrictParsers) {
  double value = 0.0;
  EXPECT_TRUE(parseFiniteDouble(" -2.5 ", value));
  EXPECT_DOUBLE_EQ(value, -2.5);
  EXPECT_FALSE(parseFiniteDouble("1e-400", value));  // underflows to a value nobody wrote
  long long integer = 0;
  EXPECT_TRUE(parseInteger("-42", integer));
  EXPECT_EQ(integer, -42);
  EXPECT_FALSE(parseInteger("4.0", integer));
  EXPECT_FALSE(parseInteger("99999999999999999999", integer));
  EXPECT_EQ(describeRange(0.0, std::numeric_limits<double>::max()), "at least 0");
  EXPECT_EQ(describeRange(-1.0, 1.0), "[-1, 1]");
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

TEST(IniKeyRecorderTest, RecordsEveryKeyAskedForWithTypeAndDefault) {
  mrpt::config::CConfigFileMemory config("[stereo]\nwindow = 9\n");
  IniKeyRecorder recorder;
  IniSection stereo(config, "stereo");
  stereo.getInt("window", 7);
  stereo.getBool("subpixel", false);
  stereo.has("rect");
  IniSection grid(config, "grid");
  grid.has("resolution");
  grid.getDouble("resolution", 0.1);
  const IniKeyRecorder::Sections& sections = recorder.sections();
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections.at("stereo").size(), 3u);
  EXPECT_EQ(sections.at("stereo").at("window").type, "integer");
  EXPECT_EQ(sections.at("stereo").at("window").default_value, "7");
  EXPECT_EQ(sections.at("stereo").at("subpixel").default_value, "false");
  EXPECT_EQ(sections.at("stereo").at("rect").type, "text");
  // The getter after has() gives the type and default.
  EXPECT_EQ(sections.at("grid").at("resolution").type, "number");
  EXPECT_EQ(sections.at("grid").at("resolution").default_value, "0.1");
}

TEST(IniKeyRecorderTest, RecordsNothingOutsideItsLifetimeAndIsAlone) {
  mrpt::config::CConfigFileMemory config("");
  IniSection before(config, "stereo");
  before.getInt("window", 7);
  {
    IniKeyRecorder recorder;
    EXPECT_THROW(IniKeyRecorder second, std::logic_error);
    EXPECT_TRUE(recorder.sections().empty());
  }
  IniKeyRecorder after;
  before.getInt("max_disparity", 15);
  EXPECT_EQ(after.sections().at("stereo").size(), 1u);
}

}  // namespace
}  // namespace stereonav
