#pragma once

#include <string>
#include <type_traits>
#include <vector>

namespace stereonav {

// Builds one JSON document for the commands' reports (stats.json, --json): objects one member
// per line, indented by depth; arrays on one line; numbers with six significant digits (%.6g),
// and null where a number is not finite (JSON has no NaN or infinity); strings escaped.
//   JsonWriter json;
//   json.beginObject().key("frames").value(12).key("stop_reason").value("done").endObject();
class JsonWriter {
 public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  // The next member's name; its value follows.
  JsonWriter& key(const std::string& name);

  JsonWriter& value(double number);
  JsonWriter& value(bool flag);
  JsonWriter& value(const std::string& text);
  JsonWriter& value(const char* text) { return value(std::string(text)); }
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
  JsonWriter& value(Integer number) {
    return raw(std::is_signed_v<Integer> ? std::to_string(static_cast<long long>(number))
                                         : std::to_string(static_cast<unsigned long long>(number)));
  }
  JsonWriter& null() { return raw("null"); }
  // A value written elsewhere as JSON text (e.g. another report's toJson()), inserted as it is.
  JsonWriter& json(const std::string& text) { return raw(text); }

  // The document, ending in a newline. Throws std::logic_error while a container is open.
  std::string str() const;

 private:
  struct Level {
    bool array = false;
    bool empty = true;
  };
  JsonWriter& raw(const std::string& text);
  // Two spaces per open object (arrays stay on their line).
  std::string indent() const;
  void beforeValue();
  void close(bool array);

  std::string out_;
  std::vector<Level> levels_;
  bool after_key_ = false;
};

}  // namespace stereonav
