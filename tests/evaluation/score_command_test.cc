// The `stereonav score` command end to end: the built binary on the shipped office run's true map.
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "support/scratch_directory.h"

namespace stereonav {
namespace {

const std::string kTruth = std::string(STEREONAV_SOURCE_DIR) + "/rawlogs/office_run.truth.yaml";

struct CommandResult {
  int exit_code;
  std::string output;  // stdout and stderr
};

class ScoreCommandTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return scratch_.file(name); }

  CommandResult run(const std::string& arguments) const {
    const std::string log = path("log.txt");
    const std::string command =
        std::string(STEREONAV_BINARY_DIR) + "/bin/stereonav score " + arguments + " > " + log + " 2>&1";
    const int status = std::system(command.c_str());
    std::stringstream output;
    output << std::ifstream(log).rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output.str()};
  }

  test_support::ScratchDirectory scratch_;
};

TEST_F(ScoreCommandTest, TheTruthScoresPerfectlyAgainstItself) {
  const CommandResult result =
      run("--map " + kTruth + " --truth " + kTruth + " --start 1.0,7.5 --json --overlay " + path("overlay.png"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("\"precision\": 1,"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("\"recall\": 1,"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("\"false_free\": 0,"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("\"coverage\": 1,"), std::string::npos) << result.output;
  const cv::Mat truth_image = cv::imread(std::string(STEREONAV_SOURCE_DIR) + "/rawlogs/office_run.truth.pgm");
  const cv::Mat overlay = cv::imread(path("overlay.png"));
  EXPECT_EQ(overlay.size(), truth_image.size());
}

TEST_F(ScoreCommandTest, TextOutputSaysWhatWasCounted) {
  const CommandResult result = run("--map " + kTruth + " --truth " + kTruth + " --tolerance 0");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("occupied precision 1.0000"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("within 0 cell(s) of a true obstacle"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("true free cells mapped free"), std::string::npos) << result.output;
}

TEST_F(ScoreCommandTest, BadInputIsOneLineNamingTheCulprit) {
  auto expectError = [&](const std::string& arguments, int code, const std::string& expected) {
    const CommandResult result = run(arguments);
    EXPECT_EQ(result.exit_code, code) << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  };
  expectError("--map " + kTruth, 2, "truth");
  expectError("--map " + kTruth + " --truth " + kTruth + " --start 1.0:7.5", 2, "--start");
  expectError("--map " + path("absent.yaml") + " --truth " + kTruth, 1, "absent.yaml");
  // (0.0, 7.5) is on the office's west wall.
  expectError("--map " + kTruth + " --truth " + kTruth + " --start 0.0,7.5", 1, "not on a free cell");
}

}  // namespace
}  // namespace stereonav
