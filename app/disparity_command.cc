#include "command_line.h"
#include "commands.h"

namespace stereonav::app {
int runDisparityCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  command_line.rejectUnknown();
  throw UsageError("not built yet");
}
}  // namespace stereonav::app
