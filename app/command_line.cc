#include "command_line.h"

#include <sys/stat.h>
#include <unistd.h>

#include <limits>

#include "common/ini_section.h"

namespace stereonav::app {

CommandLine::CommandLine(std::vector<std::string> arguments, std::set<std::string> flag_names)
    : flag_names_(std::move(flag_names)) {
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (argument.rfind("--", 0) != 0 || argument.size() == 2) {
      throw UsageError("unexpected argument '" + argument + "'");
    }
    std::string name = argument.substr(2);
    const auto equals = name.find('=');
    if (equals != std::string::npos) {
      values_.emplace(name.substr(0, equals), name.substr(equals + 1));
    } else if (flag_names_.count(name)) {
      flags_.insert(name);
    } else if (i + 1 < arguments.size()) {
      values_.emplace(name, arguments[++i]);
    } else {
      throw UsageError("--" + name + " needs a value");
    }
  }
}

std::optional<std::string> CommandLine::value(const std::string& name) {
  declared_.insert(name);
  const auto range = values_.equal_range(name);
  if (range.first == range.second) return std::nullopt;
  if (std::next(range.first) != range.second) throw UsageError("--" + name + " given more than once");
  return range.first->second;
}

std::string CommandLine::required(const std::string& name) {
  auto result = value(name);
  if (!result) throw UsageError("--" + name + " is required");
  return *result;
}

std::vector<std::string> CommandLine::values(const std::string& name) {
  declared_.insert(name);
  std::vector<std::string> result;
  const auto range = values_.equal_range(name);
  for (auto it = range.first; it != range.second; ++it) result.push_back(it->second);
  return result;
}

bool CommandLine::flag(const std::string& name) {
  declared_.insert(name);
  return flags_.count(name) > 0;
}

std::optional<int> CommandLine::intValue(const std::string& name, int min_value, int max_value) {
  const auto text = value(name);
  if (!text) return std::nullopt;
  long long result = 0;
  if (parseInteger(*text, result) && result >= min_value && result <= max_value) {
    return static_cast<int>(result);
  }
  throw UsageError("--" + name + ": expected an integer in " + std::to_string(min_value) + ".." +
                   std::to_string(max_value) + ", got '" + *text + "'");
}

std::optional<double> CommandLine::doubleValue(const std::string& name, double min_value,
                                               double max_value) {
  const auto text = value(name);
  if (!text) return std::nullopt;
  double result = 0.0;
  if (parseFiniteDouble(*text, result) && result >= min_value && result <= max_value) return result;
  throw UsageError("--" + name + ": expected " + describeRange(min_value, max_value) + ", got '" +
                   *text + "'");
}

void CommandLine::rejectUnknown() const {
  for (const auto& [name, unused] : values_) {
    if (!declared_.count(name)) throw UsageError("unknown option --" + name);
  }
  for (const auto& name : flags_) {
    if (!declared_.count(name)) throw UsageError("unknown option --" + name);
  }
}

void checkWritableFolder(const std::string& folder, const std::string& option) {
  const std::string where = folder.empty() ? "." : folder;
  struct stat status {};
  if (::stat(where.c_str(), &status) != 0 || !S_ISDIR(status.st_mode)) {
    throw UsageError(option + ": no such folder '" + where + "'");
  }
  if (::access(where.c_str(), W_OK) != 0) throw UsageError(option + ": folder '" + where + "' is not writable");
}

std::string folderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : (slash == 0 ? "/" : path.substr(0, slash));
}

void checkFileName(const std::string& path, const std::string& option) {
  if (path.empty() || path.back() == '/') throw UsageError(option + ": expected a file name, got '" + path + "'");
}

}  // namespace stereonav::app
