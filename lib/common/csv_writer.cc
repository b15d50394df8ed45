#include "common/csv_writer.h"

#include <cstdio>
#include <stdexcept>

namespace stereonav {

CsvWriter::CsvWriter(const std::vector<std::string>& columns) : columns_(columns.size()) {
  for (const std::string& column : columns) add(column);
  endRow();
}

CsvWriter& CsvWriter::field(const std::string& text) {
  if (fields_ > 0) out_ += ",";
  out_ += text;
  ++fields_;
  return *this;
}

CsvWriter& CsvWriter::add(double number) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", number);
  return field(text);
}

CsvWriter& CsvWriter::add(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return field(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return field(quoted + "\"");
}

void CsvWriter::endRow() {
  if (fields_ != columns_) {
    throw std::logic_error("CsvWriter: a row of " + std::to_string(fields_) + " fields for " +
                           std::to_string(columns_) + " columns");
  }
  out_ += "\n";
  fields_ = 0;
}

}  // namespace stereonav
