#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace stereonav {

// Thrown for any configuration mistake; what() is a one-line message naming the section and key.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` parsed as MRPT parses an ini file (expanding ${var} and $eval{...}). Throws
// ConfigError "<file_name>: <MRPT's reason, one line>" when MRPT cannot parse it.
mrpt::config::CConfigFileMemory parseConfigText(const std::string& text, const std::string& file_name);

// The ini file at `path`, parsed; ConfigError naming the file when it cannot be read or parsed.
// Every configuration and world file is opened through here.
mrpt::config::CConfigFileMemory readConfigFile(const std::string& path);

// Reads one section of an MRPT ini file and remembers every key it was asked for, so that after
// loading, a key the user wrote but nothing reads (a typo) is reported with the nearest known key
// instead of being silently ignored.
class IniSection {
 public:
  IniSection(const mrpt::config::CConfigFileBase& config, std::string section);

  const std::string& name() const { return section_; }
  bool has(const std::string& key) const;

  // Numbers are parsed strictly: the whole value must be one finite number ("1,5", "0.1abc",
  // "0.1 0.2", "nan" and "inf" are rejected) within [min_value, max_value]; otherwise ConfigError
  // names the section, the key, the allowed range and the value found.
  double getDouble(const std::string& key, double default_value,
                   double min_value = std::numeric_limits<double>::lowest(),
                   double max_value = std::numeric_limits<double>::max());
  int getInt(const std::string& key, int default_value, int min_value = std::numeric_limits<int>::min(),
             int max_value = std::numeric_limits<int>::max());
  bool getBool(const std::string& key, bool default_value);
  std::string getString(const std::string& key, const std::string& default_value);
  // As getDouble, and throws ConfigError unless the value is > 0 (>= 0 for getNonNegative) and
  // at most max_value.
  double getPositive(const std::string& key, double default_value,
                     double max_value = std::numeric_limits<double>::max());
  double getNonNegative(const std::string& key, double default_value,
                        double max_value = std::numeric_limits<double>::max());

  // Throws ConfigError naming the first key of the section that no getter asked for.
  void rejectUnknownKeys() const;

 private:
  const mrpt::config::CConfigFileBase& config_;
  std::string section_;
  std::set<std::string> known_keys_;
};

// Loads section `name` of `config` with `load` (any `Options load(IniSection&)`), then rejects the
// keys the loader did not read: the one way a whole options section is read. With `file`, errors
// start with it, so a message names the file as well as the section and key.
template <typename Load>
auto loadIniSection(const mrpt::config::CConfigFileBase& config, const std::string& name, Load load,
                    const std::string& file = "") {
  try {
    IniSection section(config, name);
    auto options = load(section);
    section.rejectUnknownKeys();
    return options;
  } catch (const ConfigError& error) {
    if (file.empty()) throw;
    throw ConfigError(file + ": " + error.what());
  }
}

// Parses the whole of `text` as one finite number; false for trailing text, NaN, infinities,
// out-of-range values and empty text. The one strict number parser (ini values, path files,
// command-line numbers).
bool parseFiniteDouble(const std::string& text, double& value);
bool parseInteger(const std::string& text, long long& value);

// "[min, max]" as written in range errors; an unbounded side is left out ("at least 0").
std::string describeRange(double min_value, double max_value);

// The known key closest to `key` by edit distance ("" if there are none).
std::string nearestKey(const std::string& key, const std::set<std::string>& known_keys);

}  // namespace stereonav
