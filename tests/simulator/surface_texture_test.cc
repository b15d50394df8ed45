#include "simulator/surface_texture.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

namespace stereonav {
namespace {

TEST(SurfaceTexture, ValueNoiseIsBoundedAndContinuous) {
  // Across zero too: lattice cells of negative coordinates start at their floor.
  double previous = valueNoise(-5.0, 0.3, 5);
  for (int i = -4999; i <= 10000; ++i) {
    const double x = i * 1e-3;
    const double value = valueNoise(x, 0.3, 5);
    ASSERT_LE(std::abs(value), 1.0);
    // The smooth-step blend has a slope of at most 1.5 * (largest lattice step, 2) per unit.
    ASSERT_LE(std::abs(value - previous), 3.0 * 1e-3 + 1e-12);
    previous = value;
  }
  EXPECT_NE(valueNoise(0.5, 0.5, 1), valueNoise(0.5, 0.5, 2));
}

TEST(SurfaceTexture, StripesAlternateWithTheirPeriodAndAverageOutWhenUnresolvable) {
  SurfaceTexture stripes;
  stripes.kind = SurfaceTexture::Kind::kStripes;
  stripes.mean = 0.5;
  stripes.contrast = 0.4;
  stripes.period_m = 0.1;
  // Sharp: lit (0.9) for the first half of each period, dark (0.1) for the second.
  EXPECT_DOUBLE_EQ(stripes.albedo(0.02, 0.0, 0.0), 0.9);
  EXPECT_DOUBLE_EQ(stripes.albedo(0.07, 0.0, 0.0), 0.1);
  EXPECT_DOUBLE_EQ(stripes.albedo(0.32, 7.0, 0.0), 0.9);
  // A pixel covering whole periods sees the mean: no aliasing.
  for (double u = 0.0; u < 0.2; u += 0.013) EXPECT_NEAR(stripes.albedo(u, 0.0, 0.1), 0.5, 1e-9);
  // A pixel over a quarter period centred on an edge sees half lit, half dark.
  EXPECT_NEAR(stripes.albedo(0.05, 0.0, 0.025), 0.5, 1e-9);
}

TEST(SurfaceTexture, NoiseDetailFadesWithThePixelFootprint) {
  SurfaceTexture noise;  // octaves 0.4, 0.1, 0.025 m
  double sharp_spread = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double u = i * 0.0137;
    sharp_spread = std::max(sharp_spread, std::abs(noise.albedo(u, 0.2, 0.001) - noise.mean));
    // A footprint of half the longest wavelength leaves nothing resolvable.
    ASSERT_DOUBLE_EQ(noise.albedo(u, 0.2, 0.2), noise.mean);
  }
  EXPECT_GT(sharp_spread, 0.1);
}

TEST(SurfaceTexture, PosterIsTexturedInsideItsFrameOnly) {
  SurfaceTexture poster;
  poster.kind = SurfaceTexture::Kind::kPoster;
  poster.poster_rect = {1.0, 1.0, 2.0, 1.5};
  EXPECT_DOUBLE_EQ(poster.albedo(0.5, 1.2, 0.001), poster.mean);
  double spread = 0.0;
  for (int i = 0; i < 100; ++i) spread = std::max(spread, std::abs(poster.albedo(1.0 + i * 0.01, 1.2, 0.001) - poster.mean));
  EXPECT_GT(spread, 0.05);
}

TEST(SurfaceTexture, NoiseFarOutOnTheLatticeIsFlat) {
  const SurfaceTexture noise;  // the finest octave 0.025 m: 4e10 lattice cells at 1e9 m
  EXPECT_DOUBLE_EQ(noise.albedo(1e9, 0.2, 0.001), noise.mean);
  EXPECT_DOUBLE_EQ(noise.albedo(0.2, -1e9, 0.001), noise.mean);
  EXPECT_DOUBLE_EQ(noise.albedo(std::nan(""), 0.2, 0.001), noise.mean);
  EXPECT_NE(noise.albedo(1e3, 0.2, 0.001), noise.mean);
}

// The sampler computes many points in vector lanes side by side: no point may depend on its
// neighbours, whatever their textures, octaves, footprints and count.
TEST(AlbedoSampler, EachPointGetsWhatItGetsAlone) {
  std::vector<SurfaceTexture> textures(6);
  textures[1].scales_m = {0.3, 0.05};
  textures[1].seed = 7;
  textures[2].kind = SurfaceTexture::Kind::kPaint;
  textures[3].kind = SurfaceTexture::Kind::kStripes;
  textures[4].kind = SurfaceTexture::Kind::kPoster;
  textures[4].poster_rect = {0.0, 0.0, 1.0, 1.0};
  textures[5].scales_m = {0.6, 0.15, 0.04, 0.01};
  textures[5].contrast = 0.6;
  std::vector<AlbedoQuery> queries;
  for (int i = 0; i < 203; ++i) {  // not a whole number of lanes
    AlbedoQuery query;
    query.texture = &textures[(i * 7) % textures.size()];
    query.u = -1.5 + 0.0173 * i;
    query.v = 0.9 - 0.011 * i;
    query.footprint_m = i % 5 == 0 ? 0.0 : 0.0007 * (i % 41);
    query.noise_shift = i % 3 == 0 ? 2.5 : 0.0;
    if (i == 50) query.u = 1e12;
    queries.push_back(query);
  }
  AlbedoSampler sampler;
  std::vector<double> together, alone;
  sampler.sample(queries, together);
  ASSERT_EQ(together.size(), queries.size());
  size_t textured = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    sampler.sample({queries[i]}, alone);
    EXPECT_EQ(together[i], alone[0]) << "point " << i;
    textured += together[i] != queries[i].texture->mean;
  }
  EXPECT_GT(textured, queries.size() / 2);  // the octaves were there to mix up
}

TEST(SurfaceTexture, LoaderRejectsBadValuesByKey) {
  const auto error = [](const std::string& text) -> std::string {
    const mrpt::config::CConfigFileMemory config(text);
    IniSection section(config, "texture.t");
    try {
      loadSurfaceTexture(section);
      section.rejectUnknownKeys();
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error("[texture.t]\ncontrast = 2\n").find("[texture.t] contrast"), std::string::npos);
  EXPECT_NE(error("[texture.t]\nscales_m = 0.1 -1\n").find("[texture.t] scales_m"), std::string::npos);
  EXPECT_NE(error("[texture.t]\nperiod = 0.1\n").find("'period_m'"), std::string::npos);
  EXPECT_NE(error("[texture.t]\norientation = diagonal\n").find("[texture.t] orientation"), std::string::npos);
  EXPECT_EQ(error("[texture.t]\ntype = stripes\nperiod_m = 0.2\norientation = horizontal\n"), "");
}

}  // namespace
}  // namespace stereonav
