#pragma once

#include <string>
#include <vector>

#include "mapping/rawlog_mapping.h"

namespace stereonav::app {

// Exit status of a job stopped before its end (a damaged input, Ctrl-C or SIGTERM) whose outputs
// hold what was done so far.
constexpr int kPartialWorkStatus = 3;

// One function per subcommand: arguments in (after the subcommand name), exit status out.
// Each lives in its own <name>_command.cc and is listed in main.cc.
int runDisparityCommand(const std::vector<std::string>& arguments);
int runSimulateCommand(const std::vector<std::string>& arguments);
int runGenerateCommand(const std::vector<std::string>& arguments);
int runMapCommand(const std::vector<std::string>& arguments);
int runExploreCommand(const std::vector<std::string>& arguments);
int runBenchExploreCommand(const std::vector<std::string>& arguments);
int runScoreCommand(const std::vector<std::string>& arguments);
int runReportCommand(const std::vector<std::string>& arguments);
int runConfigCommand(const std::vector<std::string>& arguments);
int runConvertCommand(const std::vector<std::string>& arguments);
int runCalibrateCommand(const std::vector<std::string>& arguments);

// The value of --poses (odometry | localized | ground_truth); throws UsageError naming the option.
MapPoseSource parsePosesOption(const std::string& text);

}  // namespace stereonav::app
