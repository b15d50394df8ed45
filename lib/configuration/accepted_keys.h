#pragma once

#include <string>

#include "common/ini_key_recorder.h"

namespace stereonav {

// Every ini key stereonav accepts, by section, with its value type and default: every section
// loader run on a configuration without keys (and on a world with one section of each kind) while
// an IniKeyRecorder listens. Sections whose name the user chooses carry a placeholder:
// [wall.<name>] (any world object kind), [<map>_insertOpts] (a CMultiMetricMap entry).
IniKeyRecorder::Sections acceptedConfigKeys();

// The skeleton of docs/configuration.md's key tables: per section a "### [section]" heading and
// a row "| `key` | type | default | | |" per key, to paste and fill in (range, meaning).
std::string configurationSkeleton(const IniKeyRecorder::Sections& sections);

}  // namespace stereonav
