// libFuzzer target: the rawlog reader on arbitrary bytes (plain or gzip-compressed rawlogs).
// Every input must end in frames, a clean end, or reported damage; never a crash, a leak, or
// memory beyond the deserialization budget.
#include <cstdint>

#include "fuzz_input_file.h"
#include "observations/rawlog_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  stereonav::fuzz::FuzzInputFile file(data, size, ".rawlog");
  try {
    stereonav::RawlogReader reader(file.path(), {});
    while (reader.next()) {
    }
  } catch (const std::runtime_error&) {
    // an unreadable file is reported by the constructor, naming it
  }
  return 0;
}
