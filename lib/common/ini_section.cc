#include "common/ini_section.h"

#include "common/error_text.h"
#include "common/ini_key_recorder.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace stereonav {

IniSection::IniSection(const mrpt::config::CConfigFileBase& config, std::string section)
    : config_(config), section_(std::move(section)) {}

bool IniSection::has(const std::string& key) const {
  if (IniKeyRecorder* recorder = IniKeyRecorder::active()) recorder->record(section_, key, nullptr);
  return config_.keyExists(section_, key);
}

mrpt::config::CConfigFileMemory parseConfigText(const std::string& text, const std::string& file_name) {
  try {
    return mrpt::config::CConfigFileMemory(text);
  } catch (const std::exception& error) {
    throw ConfigError(file_name + ": " + oneLineMessage(error.what()));
  }
}

mrpt::config::CConfigFileMemory readConfigFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw ConfigError(path + ": cannot open the file");
  std::ostringstream text;
  text << file.rdbuf();
  return parseConfigText(text.str(), path);
}

namespace {

// Tells the active IniKeyRecorder, if any, that `key` of `section` was read.
void recordRead(const std::string& section, const std::string& key, const char* type,
                const std::string& default_value) {
  if (IniKeyRecorder* recorder = IniKeyRecorder::active()) {
    const IniKeyRecorder::Key read{type, default_value};
    recorder->record(section, key, &read);
  }
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

bool parseFiniteDouble(const std::string& text, double& value) {
  const std::string number = trimmed(text);
  if (number.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !std::isfinite(parsed) || errno == ERANGE) {
    // ERANGE also flags underflow (1e-400); an underflow to a denormal or zero is still a value
    // the user did not mean, so it is rejected like overflow.
    return false;
  }
  value = parsed;
  return true;
}

bool parseInteger(const std::string& text, long long& value) {
  const std::string number = trimmed(text);
  if (number.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const long long parsed = std::strtoll(number.c_str(), &end, 10);
  if (end != number.c_str() + number.size() || errno == ERANGE) return false;
  value = parsed;
  return true;
}

std::string describeRange(double min_value, double max_value) {
  const bool has_min = min_value > std::numeric_limits<double>::lowest();
  const bool has_max = max_value < std::numeric_limits<double>::max();
  if (has_min && has_max) return "[" + formatNumber(min_value) + ", " + formatNumber(max_value) + "]";
  if (has_min) return "at least " + formatNumber(min_value);
  if (has_max) return "at most " + formatNumber(max_value);
  return "a finite number";
}

double IniSection::getDouble(const std::string& key, double default_value, double min_value,
                             double max_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "number", formatNumber(default_value));
  if (!config_.keyExists(section_, key)) return default_value;
  const std::string text = config_.read_string(section_, key, "");
  double value = 0.0;
  if (!parseFiniteDouble(text, value) || value < min_value || value > max_value) {
    throw ConfigError("[" + section_ + "] " + key + ": expected " + describeRange(min_value, max_value) +
                      ", got '" + text + "'");
  }
  return value;
}

int IniSection::getInt(const std::string& key, int default_value, int min_value, int max_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "integer", std::to_string(default_value));
  if (!config_.keyExists(section_, key)) return default_value;
  const std::string text = config_.read_string(section_, key, "");
  long long value = 0;
  if (!parseInteger(text, value) || value < min_value || value > max_value) {
    const bool has_min = min_value > std::numeric_limits<int>::min();
    const bool has_max = max_value < std::numeric_limits<int>::max();
    std::string allowed = "an integer";
    if (has_min && has_max) {
      allowed += " in " + std::to_string(min_value) + ".." + std::to_string(max_value);
    } else if (has_min) {
      allowed += " >= " + std::to_string(min_value);
    } else if (has_max) {
      allowed += " <= " + std::to_string(max_value);
    }
    throw ConfigError("[" + section_ + "] " + key + ": expected " + allowed + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

bool IniSection::getBool(const std::string& key, bool default_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "bool", default_value ? "true" : "false");
  std::string text = config_.read_string(section_, key, "");
  if (text.empty()) return default_value;
  std::transform(text.begin(), text.end(), text.begin(), ::tolower);
  if (text == "1" || text == "true" || text == "yes" || text == "on") return true;
  if (text == "0" || text == "false" || text == "no" || text == "off") return false;
  throw ConfigError("[" + section_ + "] " + key + ": expected true or false, got '" + text + "'");
}

std::string IniSection::getString(const std::string& key, const std::string& default_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "text", default_value);
  return config_.read_string(section_, key, default_value);
}

double IniSection::getPositive(const std::string& key, double default_value, double max_value) {
  const double value = getDouble(key, default_value, std::numeric_limits<double>::lowest(), max_value);
  if (!(value > 0.0)) {
    throw ConfigError("[" + section_ + "] " + key + ": must be positive" +
                      (max_value < std::numeric_limits<double>::max() ? " (at most " + formatNumber(max_value) + ")" : "") +
                      ", got '" + config_.read_string(section_, key, "") + "'");
  }
  return value;
}

double IniSection::getNonNegative(const std::string& key, double default_value, double max_value) {
  return getDouble(key, default_value, 0.0, max_value);
}

void IniSection::rejectUnknownKeys() const {
  std::vector<std::string> keys;
  config_.getAllKeys(section_, keys);
  for (const auto& key : keys) {
    if (known_keys_.count(key)) continue;
    std::string message = "[" + section_ + "] unknown key '" + key + "'";
    const std::string nearest = nearestKey(key, known_keys_);
    if (!nearest.empty()) message += " (did you mean '" + nearest + "'?)";
    throw ConfigError(message);
  }
}

std::string nearestKey(const std::string& key, const std::set<std::string>& known_keys) {
  std::string best;
  size_t best_distance = std::string::npos;
  for (const auto& candidate : known_keys) {
    // Levenshtein distance, one row at a time.
    std::vector<size_t> row(candidate.size() + 1);
    for (size_t j = 0; j < row.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= key.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= candidate.size(); ++j) {
        const size_t above = row[j];
        const size_t substitution = diagonal + (::tolower(key[i - 1]) != ::tolower(candidate[j - 1]));
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        diagonal = above;
      }
    }
    if (row.back() < best_distance) {
      best_distance = row.back();
      best = candidate;
    }
  }
  return best;
}

}  // namespace stereonav
