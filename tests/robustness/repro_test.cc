// The robustness failures of issue 24 (reproducers B1-B19 in tests/data/repro/), each through the
// built program: a one-line error naming the file or option, or a map up to the damage, in
// bounded time and memory. Time is the child's CPU time (not wall time, which depends on the
// machine's load); memory its peak resident set.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;

const std::string kRepro = std::string(STEREONAV_TEST_DATA_DIR) + "/repro/";
const std::string kTsukuba = std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/";
const std::string kRoot = std::string(STEREONAV_TEST_DATA_DIR) + "/../../";

// The bounds for every case.
constexpr double kMaxCpuSeconds = 2.0;
constexpr double kMaxMemoryMb = 500.0;

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Where the first line "<key> = ..." (any spaces before '=') of an ini text starts; npos if none.
size_t keyLine(const std::string& text, const std::string& key) {
  for (size_t start = 0; start < text.size();) {
    if (text.compare(start, key.size(), key) == 0) {
      const size_t equals = text.find_first_not_of(' ', start + key.size());
      if (equals != std::string::npos && text[equals] == '=') return start;
    }
    const size_t newline = text.find('\n', start);
    if (newline == std::string::npos) break;
    start = newline + 1;
  }
  return std::string::npos;
}

class ReproTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return scratch_.file(name); }

  // A copy of repro file `from` with `key = ...` lines set to `value`, written to `name`.
  std::string variant(const std::string& from, const std::string& name,
                      const std::vector<std::pair<std::string, std::string>>& values) const {
    std::string text = readAll(kRepro + from);
    for (const auto& [key, value] : values) {
      const size_t start = keyLine(text, key);
      EXPECT_NE(start, std::string::npos) << key << " not in " << from;
      if (start == std::string::npos) continue;
      const size_t end = std::min(text.find('\n', start), text.size());
      text.replace(start, end - start, key + " = " + value);
    }
    std::ofstream(path(name)) << text;
    return path(name);
  }

  // The office config of the reproducers with valid values (map_focal_nan.ini with f = 80).
  std::string officeConfig(const std::string& name,
                           std::vector<std::pair<std::string, std::string>> values = {}) const {
    values.insert(values.begin(), {"focal_px", "80"});
    return variant("map_focal_nan.ini", name, values);
  }

  // Exit `code`, a one-line error containing every one of `needles`, within the bounds.
  static void expectOneLineError(const CommandRun& run, int code, const std::vector<std::string>& needles) {
    EXPECT_EQ(run.exit_code, code) << run.err;
    EXPECT_TRUE(run.oneLineError()) << "not one line:\n" << run.err;
    for (const std::string& needle : needles) {
      EXPECT_NE(run.err.find(needle), std::string::npos) << "'" << needle << "' not named in: " << run.err;
    }
    expectBounded(run);
  }

  static void expectBounded(const CommandRun& run) {
    EXPECT_FALSE(run.timed_out);
    EXPECT_EQ(run.signal, 0) << "killed by signal " << run.signal;
    EXPECT_LT(run.cpu_seconds, kMaxCpuSeconds);
    EXPECT_LT(run.peak_memory_mb, kMaxMemoryMb);
  }

  CommandRun map(const std::string& config, const std::string& rawlog, const std::vector<std::string>& extra = {},
                 const RunOptions& options = {}) const {
    std::vector<std::string> arguments{"map", "--config", config, "--rawlog", rawlog, "--out", path("map")};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return runStereonav(arguments, options);
  }

  CommandRun simulate(const std::string& world, const std::string& plan = kRepro + "path_mini.txt") const {
    return runStereonav({"simulate", "--world", world, "--config", kRepro + "simulate.ini", "--path", plan,
                         "--out", path("sim.rawlog"), "--gt-map", path("truth.yaml")});
  }

  // No temporary file (*.tmp<pid>.*) left in the test's folder or `folder`.
  void expectNoTemporaries(const std::string& folder = "") const {
    for (const auto& entry : fs::recursive_directory_iterator(folder.empty() ? scratch_.path() : fs::path(folder))) {
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
  }

  test_support::ScratchDirectory scratch_;
};

TEST_F(ReproTest, B1HugeBaselinesAreRejectedAndTheLargestAllowedOneMatches) {
  const std::vector<std::string> base{"disparity", "--config", kRoot + "ini/tsukuba.ini", "--ref",
                                      kTsukuba + "scene1.row3.col3.ppm", "--out", path("d.pfm"), "--cam"};
  for (const std::string baseline : {"1e308:0", "1e9:0", "2147483648:0", "0:-1001"}) {
    auto arguments = base;
    arguments.push_back(kTsukuba + "scene1.row3.col4.ppm:" + baseline);
    expectOneLineError(runStereonav(arguments), 2, {"--cam", baseline});
  }
  // At the bound every candidate falls outside the image: nothing matches, nothing crashes.
  for (const std::string baseline : {"1000:0", "-1000:0", "0:1000", "1000:-1000"}) {
    auto arguments = base;
    arguments.push_back(kTsukuba + "scene1.row3.col4.ppm:" + baseline);
    const CommandRun run = runStereonav(arguments);
    EXPECT_EQ(run.exit_code, 0) << baseline << ": " << run.err;
    expectBounded(run);
  }
}

TEST_F(ReproTest, B2MrptBayesWithAHugeGridIsRejectedAtLoad) {
  expectOneLineError(map(kRepro + "map_bayes_resolution_1e-4.ini", kRepro + "office3.rawlog"), 1,
                     {"map_bayes_resolution_1e-4.ini", "[grid] resolution"});
  const std::string huge = officeConfig("bayes_wide.ini", {{"model", "mrpt_bayes"}, {"max_x", "900000"}});
  expectOneLineError(map(huge, kRepro + "office3.rawlog"), 1, {"bayes_wide.ini", "[grid]", "max_cells"});
}

TEST_F(ReproTest, B3NanCalibrationIsRejectedNamingTheKey) {
  expectOneLineError(map(kRepro + "map_focal_nan.ini", kRepro + "office3.rawlog"), 1,
                     {"map_focal_nan.ini", "[rig] focal_px", "nan"});
  for (const std::string key : {"cx", "baseline_m", "mount_tilt_deg", "mount_yaw_deg", "resolution"}) {
    const std::string config = officeConfig(key + ".ini", {{key, key == "resolution" ? "inf" : "nan"}});
    expectOneLineError(map(config, kRepro + "office3.rawlog"), 1, {key + ".ini", "] " + key + ":"});
  }
}

TEST_F(ReproTest, B4ExtremeValuesAreRejectedNamingTheKey) {
  expectOneLineError(map(kRepro + "map_clear_invalid_1e308.ini", kRepro + "office3.rawlog"), 1,
                     {"map_clear_invalid_1e308.ini", "clear_invalid_columns_to_m", "1e308"});
  expectOneLineError(map(officeConfig("focal.ini", {{"focal_px", "1e-308"}}), kRepro + "office3.rawlog"), 1,
                     {"focal.ini", "focal_px"});
}

TEST_F(ReproTest, B5ExtremeWorldValuesAreRejectedAndLeaveNoTemporary) {
  expectOneLineError(simulate(kRepro + "world_ceiling_1e308.ini"), 1,
                     {"world_ceiling_1e308.ini", "ceiling_height", "max_extent_m"});
  expectOneLineError(simulate(kRepro + "world_wall_thickness_1e308.ini"), 1,
                     {"world_wall_thickness_1e308.ini", "thickness", "max_extent_m"});
  EXPECT_FALSE(fs::exists(path("sim.rawlog")));
  expectNoTemporaries();
}

TEST_F(ReproTest, B6AndB12ScoreOptionsAreBounded) {
  const std::string truth = kRoot + "rawlogs/office_run.truth.yaml";
  expectOneLineError(runStereonav({"score", "--map", truth, "--truth", truth, "--tolerance", "2147483647"}), 2,
                     {"--tolerance", "0..100"});
  expectOneLineError(runStereonav({"score", "--map", truth, "--truth", truth, "--tolerance", "100000"}), 2,
                     {"--tolerance"});
  expectOneLineError(runStereonav({"score", "--map", truth, "--truth", truth, "--poses",
                                   kRoot + "rawlogs/office_run.gt.txt", "--view-range", "1e6"}),
                     2, {"--view-range"});
  // The largest allowed view range still finishes in bounded time.
  const CommandRun widest = runStereonav({"score", "--map", truth, "--truth", truth, "--poses",
                                          kRoot + "rawlogs/office_run.gt.txt", "--view-range", "100"});
  EXPECT_EQ(widest.exit_code, 0) << widest.err;
  expectBounded(widest);
}

TEST_F(ReproTest, B7FullDiskFailsNamingTheFileAndKeepsThePreviousOutputs) {
  const std::string config = officeConfig("office.ini");
  const CommandRun good = map(config, kRepro + "office3.rawlog");
  ASSERT_EQ(good.exit_code, 0) << good.err;
  const std::vector<std::string> outputs{"map.gridmap", "map.png", "map.yaml", "map.pgm", "map.3Dscene",
                                         "map.stats.json"};
  std::vector<std::string> before;
  for (const auto& name : outputs) before.push_back(readAll(path(name)));

  RunOptions full_disk;
  full_disk.file_size_limit = 2000;  // the small files fit, the maps do not
  const CommandRun run = map(config, kRepro + "office3.rawlog", {}, full_disk);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_TRUE(run.oneLineError()) << run.err;
  EXPECT_NE(run.err.find(path("map.")), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("cannot write"), std::string::npos) << run.err;
  for (size_t i = 0; i < outputs.size(); ++i) {
    const std::string after = readAll(path(outputs[i]));
    // Each output is either the previous one, untouched, or a complete new one (the small ones,
    // which fit: the same run writes the same bytes, except stats.json's timings).
    if (outputs[i] != "map.stats.json") {
      EXPECT_EQ(after, before[i]) << outputs[i];
    } else {
      EXPECT_FALSE(after.empty());
    }
  }
  expectNoTemporaries();
}

TEST_F(ReproTest, B8DamageIsOneLineOnScreenAndInStats) {
  const CommandRun run = map(kRoot + "ini/sample_trinocular.ini", kRepro + "trunc_500000.rawlog");
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_EQ(run.err.find("Call stack"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("===="), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("trunc_500000.rawlog: damaged"), std::string::npos) << run.err;
  const std::string stats = readAll(path("map.stats.json"));
  EXPECT_NE(stats.find("\"damage\": {"), std::string::npos);
  EXPECT_EQ(stats.find("Call stack"), std::string::npos);
  EXPECT_EQ(stats.find("\\n"), std::string::npos) << stats;
  expectBounded(run);
}

TEST_F(ReproTest, B9DamagedCameraRecordIsReportedInBoundedTimeAndMemory) {
  // The damaged camera record is in the first frame: nothing to map (exit 1, one line naming the
  // damage), every output written.
  const CommandRun run = map(kRoot + "ini/sample_trinocular.ini", kRepro + "rawlog_hang.rawlog");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_TRUE(run.oneLineError()) << run.err;
  EXPECT_NE(run.err.find("rawlog_hang.rawlog: damaged, reading stopped at object #2"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(path("map.gridmap")));
  expectBounded(run);
}

TEST_F(ReproTest, B10GridSizeIsBoundedByMaxCells) {
  expectOneLineError(map(kRepro + "map_cx_huge.ini", kRepro + "office3.rawlog"), 1, {"map_cx_huge.ini", "[rig] cx"});
  expectOneLineError(map(kRepro + "map_max_x_1e6.ini", kRepro + "office3.rawlog"), 1,
                     {"map_max_x_1e6.ini", "[grid]", "max_cells"});
  expectOneLineError(map(kRepro + "map_resolution_1e-7.ini", kRepro + "office3.rawlog"), 1,
                     {"map_resolution_1e-7.ini", "[grid] resolution", "[0.001, 100]"});
  // A grid capped small still maps the whole run: it stops growing and drops what is beyond.
  const CommandRun capped = map(officeConfig("capped.ini", {{"growth_margin_m", "2\nmax_cells = 20000"}}),
                                kRepro + "office3.rawlog");
  EXPECT_EQ(capped.exit_code, 0) << capped.err;
  expectBounded(capped);
}

TEST_F(ReproTest, B13AndB14NanWorldValuesAreRejected) {
  expectOneLineError(simulate(kRepro + "world_start_nan.ini"), 1, {"world_start_nan.ini", "start_pose"});
  expectOneLineError(simulate(kRepro + "world_mini.ini", kRepro + "path_nan.txt"), 1, {"path_nan.txt:1"});
  expectOneLineError(simulate(kRepro + "world_center_nan.ini"), 1, {"world_center_nan.ini", "center"});
  EXPECT_FALSE(fs::exists(path("sim.rawlog")));
}

TEST_F(ReproTest, B15NumbersWithTrailingTextAreRejected) {
  expectOneLineError(map(kRepro + "map_resolution_comma.ini", kRepro + "office3.rawlog"), 1,
                     {"map_resolution_comma.ini", "[grid] resolution", "1,5"});
  for (const std::string value : {"0.1abc", "0.1 0.2"}) {
    expectOneLineError(map(officeConfig("trailing.ini", {{"resolution", value}}), kRepro + "office3.rawlog"), 1,
                       {"trailing.ini", "[grid] resolution", value});
  }
}

TEST_F(ReproTest, B16LargeWorldsAreRejectedBeforeSimulating) {
  expectOneLineError(simulate(kRepro + "world_bounds_1e5.ini"), 1, {"world_bounds_1e5.ini", "bounds", "max_extent_m"});
  expectOneLineError(simulate(kRepro + "world_far_object.ini"), 1, {"world_far_object.ini", "[box.far] center"});
  EXPECT_FALSE(fs::exists(path("sim.rawlog")));
}

TEST_F(ReproTest, B17WindowAndTextureSigmaAreBounded) {
  expectOneLineError(runStereonav({"disparity", "--config", kRoot + "ini/tsukuba.ini", "--ref",
                                   kTsukuba + "scene1.row3.col3.ppm", "--cam", kTsukuba + "scene1.row3.col4.ppm:1:0",
                                   "--out", path("d.pfm"), "--window", "999999"}),
                     2, {"--window", "3..255"});
  expectOneLineError(map(kRepro + "map_texture_sigma_nan.ini", kRepro + "office3.rawlog"), 1,
                     {"map_texture_sigma_nan.ini", "texture_sigma"});
}

TEST_F(ReproTest, B18SigtermSavesTheMapAndLeavesNoTemporaryPanel) {
  const std::string panels = path("panels");
  fs::create_directories(panels);
  RunOptions options;
  bool sent = false;
  options.while_running = [&](pid_t child) {
    // After the first panel: the handler is installed and the mapping under way.
    if (!sent && fs::exists(panels + "/panel_000000.png")) {
      ::kill(child, SIGTERM);
      sent = true;
    }
  };
  const CommandRun run = map(officeConfig("office.ini"), kRoot + "rawlogs/office_run.rawlog",
                             {"--debug-panels", panels}, options);
  ASSERT_TRUE(sent);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("interrupted"), std::string::npos) << run.err;
  for (const std::string name : {"map.gridmap", "map.png", "map.yaml", "map.pgm", "map.3Dscene", "map.stats.json"}) {
    EXPECT_TRUE(fs::exists(path(name))) << name;
  }
  expectNoTemporaries();
}

TEST_F(ReproTest, B19BadOutputPathsFailBeforeAnyWork) {
  const std::string config = officeConfig("office.ini");
  const std::string rawlog = kRepro + "office3.rawlog";
  expectOneLineError(runStereonav({"map", "--config", config, "--rawlog", rawlog, "--out", ""}), 2, {"--out"});
  expectOneLineError(runStereonav({"map", "--config", config, "--rawlog", rawlog, "--out", path("maps/")}), 2,
                     {"--out"});
  expectOneLineError(map(config, rawlog, {"--virtual-scans", "/nonexistent/scans.rawlog"}), 2,
                     {"--virtual-scans", "/nonexistent"});
  expectOneLineError(map(config, rawlog, {"--debug-panels", path("missing")}), 2, {"--debug-panels", "missing"});
  EXPECT_FALSE(fs::exists(path("map.gridmap")));
  // An exploration would run for minutes before finding it cannot write its outputs.
  const std::vector<std::string> explore{"explore", "--config", kRoot + "ini/explore_160x120.ini", "--world",
                                         kRoot + "ini/worlds/table_room.ini", "--out"};
  std::vector<std::string> arguments = explore;
  arguments.push_back(path("missing/run"));
  expectOneLineError(runStereonav(arguments), 2, {"--out", "missing"});
  arguments = explore;
  arguments.push_back(path("runs/"));
  expectOneLineError(runStereonav(arguments), 2, {"--out"});
}

}  // namespace
}  // namespace stereonav
