#pragma once

#include <map>
#include <string>

namespace stereonav {

// While alive, collects every key that any IniSection on this thread is asked for (by a getter or
// by has()), with the getter's value type and default: run the loaders on a configuration without
// keys and it holds the keys the program accepts, which `stereonav config --keys` prints and a
// test compares with docs/configuration.md. One recorder at a time per thread.
class IniKeyRecorder {
 public:
  struct Key {
    std::string type;           // number, integer, bool or text
    std::string default_value;  // as the getter was given it ("" for text without a default)
  };
  using Sections = std::map<std::string, std::map<std::string, Key>>;

  IniKeyRecorder();
  ~IniKeyRecorder();
  IniKeyRecorder(const IniKeyRecorder&) = delete;
  IniKeyRecorder& operator=(const IniKeyRecorder&) = delete;

  const Sections& sections() const { return sections_; }

  // The recorder alive on this thread, or nullptr.
  static IniKeyRecorder* active();
  // For IniSection: a getter's type and default replace what was recorded before; a key only
  // asked about (has(), read == nullptr) is added as text without a default.
  void record(const std::string& section, const std::string& key, const Key* read);

 private:
  Sections sections_;
};

}  // namespace stereonav
