#pragma once

#include <mrpt/config/CConfigFileMemory.h>

#include <string>

#include "common/ini_section.h"

namespace stereonav::test_support {

// Loads `[section]` + `body` through `load` exactly as the applications do (loadIniSection), so
// option tests exercise the unknown-key check too.
template <typename Load>
auto loadSectionText(const std::string& section, const std::string& body, Load load) {
  const mrpt::config::CConfigFileMemory config("[" + section + "]\n" + body);
  return loadIniSection(config, section, load);
}

// The ConfigError message `action` throws, or "" when it succeeds.
template <typename Action>
std::string configErrorOf(Action action) {
  try {
    action();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

}  // namespace stereonav::test_support
