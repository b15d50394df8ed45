#include "common/ini_key_recorder.h"

#include <stdexcept>

namespace stereonav {
namespace {

thread_local IniKeyRecorder* active_recorder = nullptr;

}  // namespace

IniKeyRecorder::IniKeyRecorder() {
  if (active_recorder) throw std::logic_error("IniKeyRecorder: another recorder is active on this thread");
  active_recorder = this;
}

IniKeyRecorder::~IniKeyRecorder() { active_recorder = nullptr; }

IniKeyRecorder* IniKeyRecorder::active() { return active_recorder; }

void IniKeyRecorder::record(const std::string& section, const std::string& key, const Key* read) {
  auto& keys = sections_[section];
  if (read) {
    keys[key] = *read;
  } else {
    keys.try_emplace(key, Key{"text", ""});
  }
}

}  // namespace stereonav
