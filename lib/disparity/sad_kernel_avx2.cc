// The matching loop with 256-bit vectors (AVX2), chosen at run time (sadKernel).
//
// The file is not built with -mavx2: only what follows the target pragma below is AVX2 code. The
// standard library's and OpenCV core's inline functions that this file instantiates are compiled
// before it, for any x86-64 CPU, since the linker may keep this file's copy of them for the whole
// program. OpenCV's intrinsics are configured here as OpenCV's own dispatched code configures
// them: AVX2 and what it implies, in a namespace of their own (cv::hal_AVX2), apart from the
// 128-bit build's cv::hal_baseline.

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "disparity/disparity_image.h"
#include "disparity/sad_kernel.h"

#pragma GCC push_options
#pragma GCC target("avx2,fma,popcnt")

#include <immintrin.h>

#undef CV_SSE3
#undef CV_SSSE3
#undef CV_SSE4_1
#undef CV_SSE4_2
#undef CV_AVX
#undef CV_AVX2
#undef CV_FMA3
#define CV_SSE3 1
#define CV_SSSE3 1
#define CV_SSE4_1 1
#define CV_SSE4_2 1
#define CV_AVX 1
#define CV_AVX2 1
#define CV_FMA3 1
#define CV_CPU_DISPATCH_MODE AVX2
#include <opencv2/core/hal/intrin.hpp>

#define STEREONAV_SAD_KERNEL_NAMESPACE avx2
#include "disparity/sad_kernel_loop.h"

namespace stereonav {

const SadKernel& avx2SadKernel() {
  static const SadKernel kernel = avx2::makeSadKernel();
  return kernel;
}

}  // namespace stereonav

#pragma GCC pop_options
