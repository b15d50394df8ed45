#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/ini_section.h"

namespace stereonav {

// The albedo pattern painted on a simulated surface, a function of the surface coordinates
// (u, v) in metres, so that it is anchored to the world and every camera of the rig sees the same
// pattern at the same scene point (which is what makes the images matchable, paper section 2.2).
// The kinds reproduce the textures the paper names as hard or easy for correlation stereo
// (section 4.1): rich multi-scale texture, low-texture paint, repetitive stripes (picket fences),
// and posters (strong texture inside a frame on a blank wall).
struct SurfaceTexture {
  enum class Kind { kNoise, kPaint, kStripes, kPoster };
  Kind kind = Kind::kNoise;
  double mean = 0.5;      // mean albedo, 0..1
  double contrast = 0.3;  // albedo swing around the mean
  // kNoise and the inside of a kPoster: wavelengths of the value-noise octaves, metres.
  std::vector<double> scales_m{0.4, 0.1, 0.025};
  // kStripes: period and lit fraction of the square wave, and whether the stripes run up the
  // surface (vertical, varying along u) or across it (horizontal, varying along v).
  double period_m = 0.1;
  double duty = 0.5;
  bool vertical_stripes = true;
  // kPoster: the framed picture, as [u0, v0, u1, v1] in surface coordinates; outside is paint.
  std::array<double, 4> poster_rect{0.0, 0.0, 1.0, 1.0};
  uint32_t seed = 1;

  // Albedo in [0, 1] at (u, v), averaged over a pixel footprint of `footprint_m` metres: detail
  // finer than about two pixels fades to its mean instead of aliasing, so images do not shimmer
  // from frame to frame and the cameras agree even where the surface is seen obliquely.
  // `noise_shift` moves the noise pattern along u (Solid::texture_offset).
  double albedo(double u, double v, double footprint_m, double noise_shift = 0.0) const;
};

// Loads one [texture.NAME] section. Keys:
//   type      noise | paint | stripes | poster                     (default noise)
//   mean      mean albedo 0..1                                     (0.5)
//   contrast  albedo swing around the mean, 0..1                   (0.3; paint ignores it)
//   scales_m  noise/poster octave wavelengths in metres, "0.4 0.1 0.025"
//   period_m  stripes period (0.1);  duty  lit fraction (0.5)
//   orientation  vertical | horizontal stripes                     (vertical)
//   rect      poster frame "u0 v0 u1 v1" in surface metres         (0 0 1 1)
//   seed      noise seed (non-negative integer)                    (1)
SurfaceTexture loadSurfaceTexture(IniSection& section);

// Lattice value noise in [-1, 1], smooth between integer lattice points.
double valueNoise(double x, double y, uint32_t seed);

}  // namespace stereonav
