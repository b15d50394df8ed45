#pragma once

#include <string>
#include <type_traits>
#include <vector>

namespace stereonav {

// Builds a CSV table (RFC 4180): a header row, then one row per record, numbers with six
// significant digits (%.6g; "nan" for a value that is missing), text quoted where it must be.
//   CsvWriter csv({"t", "phase"});
//   csv.add(0.2).add("driving").endRow();
class CsvWriter {
 public:
  explicit CsvWriter(const std::vector<std::string>& columns);

  CsvWriter& add(double number);
  CsvWriter& add(const std::string& text);
  CsvWriter& add(const char* text) { return add(std::string(text)); }
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
  CsvWriter& add(Integer number) {
    return field(std::is_signed_v<Integer> ? std::to_string(static_cast<long long>(number))
                                           : std::to_string(static_cast<unsigned long long>(number)));
  }
  // Ends the row; throws std::logic_error unless it has one field per column.
  void endRow();

  std::string str() const { return out_; }

 private:
  CsvWriter& field(const std::string& text);

  size_t columns_ = 0;
  size_t fields_ = 0;
  std::string out_;
};

}  // namespace stereonav
