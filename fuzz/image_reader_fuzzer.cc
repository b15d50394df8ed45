// libFuzzer target: the disparity image readers (PFM, 16-bit PNG) on arbitrary bytes. Every input
// must be read or rejected with std::runtime_error naming the file.
#include <cstdint>
#include <stdexcept>

#include "disparity/disparity_io.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (const char* extension : {".pfm", ".png"}) {
    stereonav::fuzz::FuzzInputFile file(data, size, extension);
    try {
      stereonav::readDisparityImage(file.path());
    } catch (const std::runtime_error&) {
    }
  }
  return 0;
}
