#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>

#include <algorithm>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common/error_text.h"
#include "common/ini_section.h"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const std::vector<std::string>&);
};

const Command kCommands[] = {
    {"disparity", "disparity image of a rectified rig frame (PFM or 16-bit PNG)",
     stereonav::app::runDisparityCommand},
    {"simulate", "drive a simulated robot through a world file, recording a rawlog and ground truth",
     stereonav::app::runSimulateCommand},
    {"generate", "generate an indoor world file and its ground-truth map from a seed",
     stereonav::app::runGenerateCommand},
    {"map", "replay a rawlog through the stereo mapping pipeline into an occupancy grid",
     stereonav::app::runMapCommand},
    {"explore", "explore a simulated world closed-loop: stereo mapping plus frontier exploration",
     stereonav::app::runExploreCommand},
    {"bench-explore", "explore generated worlds K x S times in parallel: table, summary, montage",
     stereonav::app::runBenchExploreCommand},
    {"score", "score an occupancy map (ROS map_server YAML) against a ground-truth map",
     stereonav::app::runScoreCommand},
    {"report", "a page of an exploration run: map and path, coverage over time, debug panels",
     stereonav::app::runReportCommand},
    {"config", "print every ini section and key the commands accept (docs/configuration.md's skeleton)",
     stereonav::app::runConfigCommand},
    {"calibrate", "calibrate a stereo pair from chessboard image pairs (OpenCV YAML out)",
     stereonav::app::runCalibrateCommand},
    {"convert", "convert a EuRoC or KITTI dataset or a ROS bag into a rawlog, or a rawlog into a bag",
     stereonav::app::runConvertCommand},
};

// Full details (MRPT backtraces, OpenCV's own log) only with --verbose, which any command takes.
bool takeVerboseFlag(std::vector<std::string>& arguments) {
  const auto verbose = std::find(arguments.begin(), arguments.end(), "--verbose");
  if (verbose == arguments.end()) return false;
  arguments.erase(verbose);
  return true;
}

void printUsage(std::ostream& out) {
  out << "usage: stereonav <command> [options]\n\ncommands:\n";
  for (const auto& command : kCommands) out << "  " << command.name << "\t" << command.summary << "\n";
  out << "\nRun 'stereonav <command> --help' for a command's options. Any command takes --verbose:\n"
         "full error details (MRPT's backtraces, OpenCV's log).\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    printUsage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? 2 : 0;
  }
  const std::string name = argv[1];
  std::vector<std::string> arguments(argv + 2, argv + argc);
  const bool verbose = takeVerboseFlag(arguments);
  if (!verbose) cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  const auto message = [&](const std::string& text) { return verbose ? text : stereonav::oneLineMessage(text); };
  for (const auto& command : kCommands) {
    if (name != command.name) continue;
    try {
      return command.run(arguments);
    } catch (const stereonav::app::UsageError& error) {
      std::cerr << "stereonav " << name << ": " << error.what() << "\n";
      return 2;
    } catch (const std::bad_alloc&) {
      // Inputs are bounded when loaded, so this means a limit was raised past the memory there is.
      std::cerr << "stereonav " << name << ": out of memory; lower the size limits of the inputs "
                << "(e.g. [grid] max_cells, image size, disparity range)\n";
      return 1;
    } catch (const cv::Exception& error) {
      std::cerr << "stereonav " << name << ": OpenCV error in " << error.func << ": " << stereonav::oneLineMessage(error.err)
                << (verbose ? "\n" + std::string(error.what()) : "") << "\n";
      return 1;
    } catch (const std::exception& error) {
      std::cerr << "stereonav " << name << ": " << message(error.what()) << "\n";
      return 1;
    }
  }
  std::cerr << "stereonav: unknown command '" << name << "'\n";
  printUsage(std::cerr);
  return 2;
}
