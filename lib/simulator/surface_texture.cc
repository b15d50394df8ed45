#include "simulator/surface_texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/ini_section.h"
#include "simulator/number_list.h"

namespace stereonav {
namespace {

// Texture wavelengths and stripe periods, metres.
constexpr double kMinWavelength = 1e-4;
constexpr double kMaxWavelength = 1e4;
// Noise lattice coordinates beyond this (far grazing views, or no hit at all) read as flat
// texture: truncation to int32 would overflow there.
constexpr double kMaxLatticeCoordinate = 1e9;

// kNoiseLanes lanes of doubles, and of the 32-bit lattice coordinates and hashes beside them.
using Doubles = double __attribute__((vector_size(8 * kNoiseLanes)));
using Longs = int64_t __attribute__((vector_size(8 * kNoiseLanes)));
using Ints = int32_t __attribute__((vector_size(4 * kNoiseLanes)));
using Words = uint32_t __attribute__((vector_size(4 * kNoiseLanes)));

// Inlined into each build of valueNoise below (they pass whole vectors, whose ABI differs by
// instruction set).
[[gnu::always_inline]] inline Words hashLattice(Ints x, Ints y, Words seed_term) {
  // Integer avalanche mix: neighbouring lattice points get unrelated values.
  Words h = reinterpret_cast<Words&>(x) * 0x8da6b343u ^ reinterpret_cast<Words&>(y) * 0xd8163841u ^ seed_term;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

// The lattice point's value in [0, 65535]; value noise maps it to [-1, 1].
[[gnu::always_inline]] inline Ints latticeLevel(Ints x, Ints y, Words seed_term) {
  const Words low = hashLattice(x, y, seed_term) & 0xffffu;
  return reinterpret_cast<const Ints&>(low);
}

// std::clamp(value, low, high), NaN included, as a maximum and a minimum without branches: the
// branches of std::clamp went the wrong way for many of a row's pixels.
double clampBetween(double value, double low, double high) { return std::min(std::max(value, low), high); }

// How much of an octave of wavelength `wavelength` survives a pixel footprint: all of it above
// four pixels per wavelength, none below two (where it could only alias). Written with the
// footprint's inverse: the division is done once per pixel, not once per octave.
double octaveWeight(double wavelength, double inverse_footprint) {
  return clampBetween((wavelength * inverse_footprint - 2.0) / 2.0, 0.0, 1.0);
}

// Second integral of the unit square wave (1 on the first `duty` of each period) from 0 to s,
// s >= 0: the tent filter below is its second difference.
double squareWaveSecondIntegral(double s, double period, double duty) {
  const double lit = duty * period;
  const double cycles = std::floor(s / period);
  const double r = s - cycles * period;
  const double whole_cycles = lit * period * cycles * (cycles - 1.0) / 2.0 + cycles * (lit * period - lit * lit / 2.0);
  const double partial = cycles * lit * r + (r <= lit ? r * r / 2.0 : lit * lit / 2.0 + lit * (r - lit));
  return whole_cycles + partial;
}

double stripes(const SurfaceTexture& texture, double u, double v, double footprint) {
  const double period = texture.period_m;
  const double s = texture.vertical_stripes ? u : v;
  // Only the phase matters; measuring from a period boundary a few periods back keeps the
  // integrals small and the arguments non-negative.
  const double phase = s - std::floor(s / period) * period;
  double lit;
  if (footprint <= 1e-9) {
    lit = phase < texture.duty * period ? 1.0 : 0.0;
  } else {
    // Tent filter of half-width `footprint` (a pixel's footprint blurred by its neighbours'),
    // done exactly through the second integral: unlike a box filter it leaves no visible moire
    // when a pixel covers a non-integer number of periods.
    const double origin = (std::ceil(footprint / period) + 1.0) * period;
    const double at = origin + phase;
    lit = (squareWaveSecondIntegral(at + footprint, period, texture.duty) -
           2.0 * squareWaveSecondIntegral(at, period, texture.duty) +
           squareWaveSecondIntegral(at - footprint, period, texture.duty)) /
          (footprint * footprint);
  }
  return 2.0 * lit - 1.0;
}

// A texture's albedo for a signal in [-1, 1] (noise or stripes) around its mean.
double albedoOfSignal(const SurfaceTexture& texture, double signal) {
  return clampBetween(texture.mean + texture.contrast * signal, 0.0, 1.0);
}

}  // namespace

// Built for AVX2 as well (chosen at load time): the lanes then fill whole vector registers. Not
// with FMA, whose fused rounding would change the images from one machine to another.
__attribute__((target_clones("avx2", "default")))
void valueNoise(const double* x, const double* y, const uint32_t* seed, double* noise, size_t n) {
  const Doubles zero{};
  for (size_t i = 0; i < n; i += kNoiseLanes) {
    Doubles px, py;
    Words seeds;
    std::memcpy(&px, x + i, sizeof px);
    std::memcpy(&py, y + i, sizeof py);
    std::memcpy(&seeds, seed + i, sizeof seeds);
    // Far lattice coordinates (or NaN) read as flat texture, computed at 0 to keep the int
    // conversion in range.
    const Longs inside = ((px < zero ? -px : px) < kMaxLatticeCoordinate) &
                         ((py < zero ? -py : py) < kMaxLatticeCoordinate);
    px = inside ? px : zero;
    py = inside ? py : zero;
    // Truncation corrected for negative values: floor.
    Ints ix = __builtin_convertvector(px, Ints);
    Ints iy = __builtin_convertvector(py, Ints);
    ix += __builtin_convertvector(px < __builtin_convertvector(ix, Doubles), Ints);
    iy += __builtin_convertvector(py < __builtin_convertvector(iy, Doubles), Ints);
    const Doubles tx = px - __builtin_convertvector(ix, Doubles);
    const Doubles ty = py - __builtin_convertvector(iy, Doubles);
    const Doubles sx = tx * tx * (3.0 - 2.0 * tx);
    const Doubles sy = ty * ty * (3.0 - 2.0 * ty);
    const Words seed_term = seeds * 0xcb1ab31fu;
    constexpr double kLevelToUnit = 2.0 / 65535.0;
    const Doubles a = __builtin_convertvector(latticeLevel(ix, iy, seed_term), Doubles) * kLevelToUnit - 1.0;
    const Doubles b = __builtin_convertvector(latticeLevel(ix + 1, iy, seed_term), Doubles) * kLevelToUnit - 1.0;
    const Doubles c = __builtin_convertvector(latticeLevel(ix, iy + 1, seed_term), Doubles) * kLevelToUnit - 1.0;
    const Doubles d = __builtin_convertvector(latticeLevel(ix + 1, iy + 1, seed_term), Doubles) * kLevelToUnit - 1.0;
    const Doubles value = (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
    const Doubles kept = inside ? value : zero;
    std::memcpy(noise + i, &kept, sizeof kept);
  }
}

namespace {

// albedoOfSignal of the noise signals of n queries (each its weighted sum of octaves over the square
// root of its octave count, scaled to about one standard deviation), a vector of them at a time:
// one by one, each waited for its division before the branches of its clamp. Every array holds n
// rounded up to a multiple of kNoiseLanes elements. Built for AVX2 as well, not with FMA (see
// valueNoise).
__attribute__((target_clones("avx2", "default")))
void albedosOfNoise(const double* sums, const double* means, const double* contrasts, const double* octave_roots,
                    double* albedos, size_t n) {
  const Doubles zero{}, one = zero + 1.0;
  for (size_t i = 0; i < n; i += kNoiseLanes) {
    Doubles sum, mean, contrast, octave_root;
    std::memcpy(&sum, sums + i, sizeof sum);
    std::memcpy(&mean, means + i, sizeof mean);
    std::memcpy(&contrast, contrasts + i, sizeof contrast);
    std::memcpy(&octave_root, octave_roots + i, sizeof octave_root);
    // Interpolated value noise has a standard deviation near 1/3 per octave.
    const Doubles albedo = mean + contrast * (sum * 3.0 / octave_root);
    // clampBetween(albedo, 0, 1), lane by lane.
    const Doubles at_least_zero = albedo < zero ? zero : albedo;
    const Doubles clamped = one < at_least_zero ? one : at_least_zero;
    std::memcpy(albedos + i, &clamped, sizeof clamped);
  }
}

}  // namespace

double valueNoise(double x, double y, uint32_t seed) {
  double xs[kNoiseLanes] = {x}, ys[kNoiseLanes] = {y}, noise[kNoiseLanes];
  uint32_t seeds[kNoiseLanes] = {seed};
  valueNoise(xs, ys, seeds, noise, 1);
  return noise[0];
}

double SurfaceTexture::albedo(double u, double v, double footprint_m, double noise_shift) const {
  AlbedoSampler sampler;
  std::vector<double> albedos;
  sampler.sample({AlbedoQuery{this, u, v, footprint_m, noise_shift}}, albedos);
  return albedos[0];
}

void AlbedoSampler::growPoints(size_t points) {
  if (x_.size() >= points + kNoiseLanes) return;
  const size_t size = 2 * (points + kNoiseLanes);
  x_.resize(size);
  y_.resize(size);
  seed_.resize(size);
  weight_.resize(size);
  noise_.resize(size);
}

void AlbedoSampler::sample(const std::vector<AlbedoQuery>& queries, std::vector<double>& albedos) {
  albedos.resize(queries.size());
  // The lattice points of every octave of every query that needs the noise, query by query,
  // each query's in octave order: its sum then adds them in the order albedo() does.
  noisy_.clear();
  points_end_.clear();
  means_.clear();
  contrasts_.clear();
  octave_roots_.clear();
  size_t count = 0;
  const SurfaceTexture* texture_seen = nullptr;  // the last texture's octaves, kept (rows share few)
  double octave_root = 1.0;                      // and the square root of their count
  for (size_t i = 0; i < queries.size(); ++i) {
    const AlbedoQuery& query = queries[i];
    const SurfaceTexture& texture = *query.texture;
    switch (texture.kind) {
      case SurfaceTexture::Kind::kPaint:
        albedos[i] = texture.mean;
        continue;
      case SurfaceTexture::Kind::kStripes:
        albedos[i] = albedoOfSignal(texture, stripes(texture, query.u, query.v, query.footprint_m));
        continue;
      case SurfaceTexture::Kind::kPoster: {
        const auto& rect = texture.poster_rect;
        if (query.u < rect[0] || query.u > rect[2] || query.v < rect[1] || query.v > rect[3]) {
          albedos[i] = texture.mean;
          continue;
        }
        break;
      }
      case SurfaceTexture::Kind::kNoise:
        break;
    }
    const size_t octaves = texture.scales_m.size();
    if (&texture != texture_seen) {
      texture_seen = &texture;
      inverse_wavelengths_.resize(octaves);
      octave_seeds_.resize(octaves);
      for (size_t octave = 0; octave < octaves; ++octave) {
        inverse_wavelengths_[octave] = 1.0 / texture.scales_m[octave];
        octave_seeds_[octave] = texture.seed + 1013u * static_cast<uint32_t>(octave);
      }
      octave_root = std::sqrt(static_cast<double>(octaves));
    }
    growPoints(count + octaves);
    const double inverse_footprint =
        query.footprint_m > 0.0 ? 1.0 / query.footprint_m : std::numeric_limits<double>::infinity();
    const double u = query.u + query.noise_shift;
    for (size_t octave = 0; octave < octaves; ++octave) {
      // Written whatever the weight and kept only if it is not zero: which octaves a pixel's
      // footprint keeps changes from pixel to pixel, too often for a branch to guess.
      const double weight = octaveWeight(texture.scales_m[octave], inverse_footprint);
      x_[count] = u * inverse_wavelengths_[octave];
      y_[count] = query.v * inverse_wavelengths_[octave];
      seed_[count] = octave_seeds_[octave];
      weight_[count] = weight;
      count += weight != 0.0;
    }
    noisy_.push_back(i);
    points_end_.push_back(count);
    means_.push_back(texture.mean);
    contrasts_.push_back(texture.contrast);
    octave_roots_.push_back(octave_root);
  }
  // The lanes past the last point: defined values, their noise unused.
  growPoints(count);
  std::fill(x_.begin() + count, x_.begin() + count + kNoiseLanes, 0.0);
  std::fill(y_.begin() + count, y_.begin() + count + kNoiseLanes, 0.0);
  valueNoise(x_.data(), y_.data(), seed_.data(), noise_.data(), count);

  const size_t noisy = noisy_.size();
  const size_t lanes = (noisy + kNoiseLanes - 1) / kNoiseLanes * kNoiseLanes;
  sums_.resize(lanes);
  noisy_albedos_.resize(lanes);
  // The spare lanes: defined values, their albedos unused.
  means_.resize(lanes, 0.0);
  contrasts_.resize(lanes, 0.0);
  octave_roots_.resize(lanes, 1.0);
  size_t point = 0;
  for (size_t j = 0; j < noisy; ++j) {
    double sum = 0.0;
    for (; point < points_end_[j]; ++point) sum += weight_[point] * noise_[point];
    sums_[j] = sum;
  }
  std::fill(sums_.begin() + static_cast<std::ptrdiff_t>(noisy), sums_.end(), 0.0);
  albedosOfNoise(sums_.data(), means_.data(), contrasts_.data(), octave_roots_.data(), noisy_albedos_.data(), lanes);
  for (size_t j = 0; j < noisy; ++j) albedos[noisy_[j]] = noisy_albedos_[j];
}

SurfaceTexture loadSurfaceTexture(IniSection& section) {
  const auto where = [&](const std::string& key) { return "[" + section.name() + "] " + key; };
  SurfaceTexture texture;
  const std::string type = section.getString("type", "noise");
  if (type == "noise") {
    texture.kind = SurfaceTexture::Kind::kNoise;
  } else if (type == "paint") {
    texture.kind = SurfaceTexture::Kind::kPaint;
  } else if (type == "stripes") {
    texture.kind = SurfaceTexture::Kind::kStripes;
  } else if (type == "poster") {
    texture.kind = SurfaceTexture::Kind::kPoster;
  } else {
    throw ConfigError(where("type") + ": expected noise, paint, stripes or poster, got '" + type + "'");
  }
  texture.mean = section.getDouble("mean", texture.mean, 0.0, 1.0);
  texture.contrast = section.getDouble("contrast", texture.contrast, 0.0, 1.0);
  if (section.has("scales_m")) {
    texture.scales_m = parseNumberList(section.getString("scales_m", ""), where("scales_m"));
  }
  texture.period_m = section.getPositive("period_m", texture.period_m, kMaxWavelength);
  texture.duty = section.getDouble("duty", texture.duty, 0.0, 1.0);
  const std::string orientation = section.getString("orientation", "vertical");
  if (orientation != "vertical" && orientation != "horizontal") {
    throw ConfigError(where("orientation") + ": expected vertical or horizontal, got '" +
                      orientation + "'");
  }
  texture.vertical_stripes = orientation == "vertical";
  if (section.has("rect")) {
    const auto rect = parseNumberList(section.getString("rect", ""), where("rect"), 4);
    std::copy(rect.begin(), rect.end(), texture.poster_rect.begin());
  }
  const int seed = section.getInt("seed", static_cast<int>(texture.seed));
  if (seed < 0) throw ConfigError(where("seed") + ": must be non-negative");
  texture.seed = static_cast<uint32_t>(seed);

  if (texture.mean < 0.0 || texture.mean > 1.0) throw ConfigError(where("mean") + ": must be in [0, 1]");
  if (texture.contrast < 0.0 || texture.contrast > 1.0) {
    throw ConfigError(where("contrast") + ": must be in [0, 1]");
  }
  if (texture.scales_m.empty()) throw ConfigError(where("scales_m") + ": needs at least one wavelength");
  for (double scale : texture.scales_m) {
    // Bounded below so that world coordinates (metres) over a wavelength stay well inside the
    // noise lattice's integer range.
    if (!(scale >= kMinWavelength && scale <= kMaxWavelength)) {
      throw ConfigError(where("scales_m") + ": wavelengths must be in " +
                        describeRange(kMinWavelength, kMaxWavelength) + " m");
    }
  }
  if (texture.period_m <= 0.0) throw ConfigError(where("period_m") + ": must be positive");
  if (texture.duty <= 0.0 || texture.duty >= 1.0) throw ConfigError(where("duty") + ": must be in (0, 1)");
  if (texture.poster_rect[2] <= texture.poster_rect[0] || texture.poster_rect[3] <= texture.poster_rect[1]) {
    throw ConfigError(where("rect") + ": expected u0 v0 u1 v1 with u1 > u0 and v1 > v0");
  }
  return texture;
}

}  // namespace stereonav
