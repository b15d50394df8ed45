#include "simulator/surface_texture.h"

#include <algorithm>
#include <cmath>
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

uint32_t hashLattice(int32_t x, int32_t y, uint32_t seed) {
  // Integer avalanche mix: neighbouring lattice points get unrelated values.
  uint32_t h = static_cast<uint32_t>(x) * 0x8da6b343u ^ static_cast<uint32_t>(y) * 0xd8163841u ^
               seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

double latticeValue(int32_t x, int32_t y, uint32_t seed) {
  return (hashLattice(x, y, seed) & 0xffffu) * (2.0 / 65535.0) - 1.0;
}

// valueNoise()'s body, inline here: multiScaleNoise runs it for every octave of every pixel,
// and the exported function is called through the library's symbol table.
inline double latticeNoise(double x, double y, uint32_t seed) {
  // Truncation corrected for negative values: std::floor is a library call on baseline x86-64,
  // and this runs several times per pixel.
  if (!(std::abs(x) < kMaxLatticeCoordinate && std::abs(y) < kMaxLatticeCoordinate)) return 0.0;
  int32_t ix = static_cast<int32_t>(x);
  int32_t iy = static_cast<int32_t>(y);
  ix -= x < ix;
  iy -= y < iy;
  const double tx = x - ix;
  const double ty = y - iy;
  const double sx = tx * tx * (3.0 - 2.0 * tx);
  const double sy = ty * ty * (3.0 - 2.0 * ty);
  const double a = latticeValue(ix, iy, seed);
  const double b = latticeValue(ix + 1, iy, seed);
  const double c = latticeValue(ix, iy + 1, seed);
  const double d = latticeValue(ix + 1, iy + 1, seed);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

// How much of an octave of wavelength `wavelength` survives a pixel footprint: all of it above
// four pixels per wavelength, none below two (where it could only alias). Written with the
// footprint's inverse: the division is done once per pixel, not once per octave.
double octaveWeight(double wavelength, double inverse_footprint) {
  return std::clamp((wavelength * inverse_footprint - 2.0) / 2.0, 0.0, 1.0);
}

double multiScaleNoise(const SurfaceTexture& texture, double u, double v, double footprint) {
  const double inverse_footprint = footprint > 0.0 ? 1.0 / footprint : std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (size_t i = 0; i < texture.scales_m.size(); ++i) {
    const double wavelength = texture.scales_m[i];
    const double weight = octaveWeight(wavelength, inverse_footprint);
    if (weight == 0.0) continue;
    const double inverse_wavelength = 1.0 / wavelength;
    sum += weight * latticeNoise(u * inverse_wavelength, v * inverse_wavelength, texture.seed + 1013u * i);
  }
  // Interpolated value noise has a standard deviation near 1/3 per octave.
  return sum * 3.0 / std::sqrt(static_cast<double>(texture.scales_m.size()));
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

}  // namespace

double valueNoise(double x, double y, uint32_t seed) { return latticeNoise(x, y, seed); }

double SurfaceTexture::albedo(double u, double v, double footprint_m, double noise_shift) const {
  double signal = 0.0;
  switch (kind) {
    case Kind::kPaint:
      return mean;
    case Kind::kNoise:
      signal = multiScaleNoise(*this, u + noise_shift, v, footprint_m);
      break;
    case Kind::kStripes:
      signal = stripes(*this, u, v, footprint_m);
      break;
    case Kind::kPoster:
      if (u < poster_rect[0] || u > poster_rect[2] || v < poster_rect[1] || v > poster_rect[3]) {
        return mean;
      }
      signal = multiScaleNoise(*this, u + noise_shift, v, footprint_m);
      break;
  }
  return std::clamp(mean + contrast * signal, 0.0, 1.0);
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
