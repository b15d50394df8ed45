#include "common/json_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace stereonav {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

std::string JsonWriter::indent() const {
  const auto objects = std::count_if(levels_.begin(), levels_.end(), [](const Level& level) { return !level.array; });
  return std::string(2 * static_cast<size_t>(objects), ' ');
}

void JsonWriter::beforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (levels_.empty()) {
    if (!out_.empty()) throw std::logic_error("JsonWriter: a second top-level value");
    return;
  }
  Level& level = levels_.back();
  if (!level.array) throw std::logic_error("JsonWriter: an object member without a key");
  if (!level.empty) out_ += ", ";
  level.empty = false;
}

JsonWriter& JsonWriter::raw(const std::string& text) {
  beforeValue();
  out_ += text;
  return *this;
}

JsonWriter& JsonWriter::beginObject() {
  raw("{");
  levels_.push_back({false, true});
  return *this;
}

JsonWriter& JsonWriter::beginArray() {
  raw("[");
  levels_.push_back({true, true});
  return *this;
}

void JsonWriter::close(bool array) {
  if (levels_.empty() || levels_.back().array != array || after_key_) {
    throw std::logic_error("JsonWriter: unbalanced end of a container");
  }
  const bool empty = levels_.back().empty;
  levels_.pop_back();
  if (!array && !empty) out_ += "\n" + indent();
  out_ += array ? "]" : "}";
}

JsonWriter& JsonWriter::endObject() {
  close(false);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  close(true);
  return *this;
}

JsonWriter& JsonWriter::key(const std::string& name) {
  if (levels_.empty() || levels_.back().array || after_key_) throw std::logic_error("JsonWriter: a key outside an object");
  Level& level = levels_.back();
  if (!level.empty) out_ += ",";
  level.empty = false;
  out_ += "\n" + indent() + quoted(name) + ": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double number) {
  if (!std::isfinite(number)) return null();
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", number);
  return raw(text);
}

JsonWriter& JsonWriter::value(bool flag) { return raw(flag ? "true" : "false"); }

JsonWriter& JsonWriter::value(const std::string& text) { return raw(quoted(text)); }

std::string JsonWriter::str() const {
  if (!levels_.empty() || after_key_) throw std::logic_error("JsonWriter: the document is not complete");
  return out_ + "\n";
}

}  // namespace stereonav
