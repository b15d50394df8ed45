#include "common/ini_section.h"

#include "common/ini_key_recorder.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace stereonav {
namespace {

// Tells the active IniKeyRecorder, if any, that `key` of `section` was read.
void recordRead(const std::string& section, const std::string& key, const char* type,
                const std::string& default_value) {
  if (IniKeyRecorder* recorder = IniKeyRecorder::active()) {
    const IniKeyRecorder::Key read{type, default_value};
    recorder->record(section, key, &read);
  }
}

std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

IniSection::IniSection(const mrpt::config::CConfigFileBase& config, std::string section)
    : config_(config), section_(std::move(section)) {}

bool IniSection::has(const std::string& key) const {
  if (IniKeyRecorder* recorder = IniKeyRecorder::active()) recorder->record(section_, key, nullptr);
  return config_.keyExists(section_, key);
}

double IniSection::getDouble(const std::string& key, double default_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "number", numberText(default_value));
  try {
    return config_.read_double(section_, key, default_value);
  } catch (const std::exception&) {
    throw ConfigError("[" + section_ + "] " + key + ": expected a number, got '" +
                      config_.read_string(section_, key, "") + "'");
  }
}

int IniSection::getInt(const std::string& key, int default_value) {
  known_keys_.insert(key);
  recordRead(section_, key, "integer", std::to_string(default_value));
  const std::string text = config_.read_string(section_, key, "");
  if (text.empty()) return default_value;
  try {
    size_t used = 0;
    const int value = std::stoi(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  throw ConfigError("[" + section_ + "] " + key + ": expected an integer, got '" + text + "'");
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

double IniSection::getPositive(const std::string& key, double default_value) {
  const double value = getDouble(key, default_value);
  if (!(value > 0.0)) throw ConfigError("[" + section_ + "] " + key + ": must be positive");
  return value;
}

double IniSection::getNonNegative(const std::string& key, double default_value) {
  const double value = getDouble(key, default_value);
  if (!(value >= 0.0)) throw ConfigError("[" + section_ + "] " + key + ": must not be negative");
  return value;
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
