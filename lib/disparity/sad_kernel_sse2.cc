// The matching loop with 128-bit vectors (SSE2, part of every x86-64 CPU).

#include <opencv2/core/hal/intrin.hpp>

#define STEREONAV_SAD_KERNEL_NAMESPACE sse2
#include "disparity/sad_kernel_loop.h"

namespace stereonav {

const SadKernel& sse2SadKernel() {
  static const SadKernel kernel = sse2::makeSadKernel();
  return kernel;
}

}  // namespace stereonav
