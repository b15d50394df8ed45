#pragma once

#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace stereonav::app {

// A usage mistake; what() is the one-line message printed before exiting with status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// GNU-style "--name value" / "--flag" arguments of one subcommand. Every option the command
// understands is declared through one of the getters; rejectUnknown() then reports the rest.
class CommandLine {
 public:
  CommandLine(std::vector<std::string> arguments, std::set<std::string> flag_names);

  std::optional<std::string> value(const std::string& name);
  std::string required(const std::string& name);
  std::vector<std::string> values(const std::string& name);
  bool flag(const std::string& name);
  // Strict numbers (the whole value, finite) within [min_value, max_value], else UsageError
  // naming the option and the range.
  std::optional<int> intValue(const std::string& name, int min_value = std::numeric_limits<int>::min(),
                              int max_value = std::numeric_limits<int>::max());
  std::optional<double> doubleValue(const std::string& name,
                                    double min_value = std::numeric_limits<double>::lowest(),
                                    double max_value = std::numeric_limits<double>::max());
  void rejectUnknown() const;

 private:
  std::multimap<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::set<std::string> flag_names_;
  std::set<std::string> declared_;
};

// Checked before any work, so that a typo in a path does not cost the run: UsageError naming
// `option` unless `folder` ("" = the current one) exists and is writable.
void checkWritableFolder(const std::string& folder, const std::string& option);
// The folder part of `path` ("" for a bare name).
std::string folderOf(const std::string& path);
// A prefix or file name, not a folder: "--out maps/" would write hidden files "maps/.gridmap".
void checkFileName(const std::string& path, const std::string& option);

}  // namespace stereonav::app
