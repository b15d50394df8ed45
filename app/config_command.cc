#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "configuration/accepted_keys.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav config --keys\n"
    "Prints every ini section and key stereonav accepts, with its type and default, as the\n"
    "Markdown tables of docs/configuration.md (range and meaning left blank): the skeleton to\n"
    "paste when a key is added. [wall.<name>] stands for any world object section, <map> for a\n"
    "CMultiMetricMap entry's prefix.\n";

}  // namespace

int runConfigCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help", "keys"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const bool keys = command_line.flag("keys");
  command_line.rejectUnknown();
  if (!keys) throw UsageError("nothing to do: give --keys");
  std::cout << configurationSkeleton(acceptedConfigKeys());
  return 0;
}

}  // namespace stereonav::app
