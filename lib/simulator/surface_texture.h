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
  // One point at a time; AlbedoSampler does many at once with the same result.
  double albedo(double u, double v, double footprint_m, double noise_shift = 0.0) const;
};

// SurfaceTexture::albedo's arguments for one point.
struct AlbedoQuery {
  const SurfaceTexture* texture = nullptr;
  double u = 0.0, v = 0.0, footprint_m = 0.0, noise_shift = 0.0;
};

// The albedos of many points at once, bit for bit what albedo() gives each alone: each noise
// octave of all the points runs as one vector loop over them. Point by point, the value noise
// took a fifth of an exploration run (a camera row of points is a good batch). Keeps its buffers
// from call to call.
class AlbedoSampler {
 public:
  // albedos[i] = queries[i].texture->albedo(...) for every i.
  void sample(const std::vector<AlbedoQuery>& queries, std::vector<double>& albedos);

 private:
  // Room for this many lattice points and the spare lanes after them.
  void growPoints(size_t points);

  std::vector<size_t> noisy_;       // the queries that need the noise
  std::vector<size_t> points_end_;  // and where each one's lattice points end
  // Per noisy query, kNoiseLanes spare lanes at the end: its texture's mean, contrast and square
  // root of its octave count, its weighted sum of noise, and its albedo.
  std::vector<double> means_, contrasts_, octave_roots_, sums_, noisy_albedos_;
  // The lattice points (x, y, seed) of every octave of those queries, their weights and noise;
  // kNoiseLanes spare lanes at the end.
  std::vector<double> x_, y_, weight_, noise_;
  std::vector<uint32_t> seed_;
  // One texture's octaves.
  std::vector<double> inverse_wavelengths_;
  std::vector<uint32_t> octave_seeds_;
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
// valueNoise of n points, into `noise`; every array holds n rounded up to a multiple of
// kNoiseLanes elements (the lanes past n are computed and ignored).
constexpr size_t kNoiseLanes = 4;
void valueNoise(const double* x, const double* y, const uint32_t* seed, double* noise, size_t n);

}  // namespace stereonav
