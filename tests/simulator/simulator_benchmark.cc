// Rendering cost of one trinocular frame (the reference and two secondary cameras plus the true
// disparity) at the paper's 160 x 120 (section 3.3) and at 320 x 240, in the bundled worlds; and
// the ray caster's 2D grid against its peer, testing every solid of the world for every ray.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "simulator/moving_traffic.h"
#include "simulator/ray_caster.h"

#include "simulator/rig_renderer.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

std::string worldPath(const char* name) {
  return std::string(STEREONAV_TEST_DATA_DIR) + "/../../ini/worlds/" + name;
}

void renderFrames(benchmark::State& state, const char* world_name, int width) {
  const World world = loadWorld(worldPath(world_name));
  CameraRig rig;
  rig.reference = {width, width * 3 / 4, width / 2.0, (width - 1) / 2.0, (width * 3 / 4 - 1) / 2.0};
  RigRenderer renderer(world, rig, SensorOptions{});
  mrpt::poses::CPose2D pose(world.start_pose[0], world.start_pose[1], world.start_pose[2]);
  MovingTraffic traffic(world);
  double time = 0.0;
  for (auto _ : state) {
    // Turn on the spot so every frame sees a different part of the world.
    pose.phi_incr(0.2);
    time += 0.2;
    traffic.advance(0.2, pose, 0.0, 0.3);
    benchmark::DoNotOptimize(renderer.render(pose, time, traffic.solids()));
  }
  state.counters["rays/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * width * (width * 3 / 4) * 3, benchmark::Counter::kIsRate);
}

void BM_RenderTrinocular160x120_Office(benchmark::State& state) { renderFrames(state, "office.ini", 160); }
void BM_RenderTrinocular160x120_TableRoom(benchmark::State& state) { renderFrames(state, "table_room.ini", 160); }
void BM_RenderTrinocular160x120_PicketFence(benchmark::State& state) {
  renderFrames(state, "picket_fence.ini", 160);
}
void BM_RenderTrinocular320x240_Office(benchmark::State& state) { renderFrames(state, "office.ini", 320); }

// Rays as a camera at the office's start sees them: from 0.75 m up, all around, within 30 degrees
// of the horizontal.
std::vector<Ray> officeRays(const World& world) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> slope(-0.58, 0.58);
  std::vector<Ray> rays;
  for (int i = 0; i < 4096; ++i) {
    const double a = angle(random);
    rays.push_back({Eigen::Vector3d(world.start_pose[0], world.start_pose[1], 0.75),
                    Eigen::Vector3d(std::cos(a), std::sin(a), slope(random))});
  }
  return rays;
}

void BM_CastRays_Office_Grid(benchmark::State& state) {
  const World world = loadWorld(worldPath("office.ini"));
  RayCaster caster(world);
  const std::vector<Ray> rays = officeRays(world);
  for (auto _ : state) {
    for (const Ray& ray : rays) benchmark::DoNotOptimize(caster.cast(ray).t);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
}

void BM_CastRays_Office_EverySolid(benchmark::State& state) {
  const World world = loadWorld(worldPath("office.ini"));
  const std::vector<Ray> rays = officeRays(world);
  for (auto _ : state) {
    for (const Ray& ray : rays) {
      double nearest = std::min(intersectHorizontalPlane(0.0, ray, kNoHit),
                                intersectHorizontalPlane(world.ceiling_height, ray, kNoHit));
      for (const Solid& solid : world.solids) {
        int face = 0;
        nearest = std::min(nearest, intersectSolid(solid, ray, nearest, &face));
      }
      benchmark::DoNotOptimize(nearest);
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
}

BENCHMARK(BM_CastRays_Office_Grid);
BENCHMARK(BM_CastRays_Office_EverySolid);
BENCHMARK(BM_RenderTrinocular160x120_Office)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_TableRoom)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_PicketFence)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular320x240_Office)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
