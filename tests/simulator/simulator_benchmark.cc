// Rendering cost of one trinocular frame (the reference and two secondary cameras plus the true
// disparity) at the paper's 160 x 120 (section 3.3) and at 320 x 240, in the bundled worlds; and
// the ray caster's silhouettes against their peer, testing every solid of the world for every pixel.
#include <benchmark/benchmark.h>
#include <Eigen/Geometry>

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

// The 320 x 240 view of a camera 1.1 m up at the office's start, looking 20 degrees down, turned
// by `yaw` (as the explore config's head sees the world).
PixelRays officeView(const World& world, double yaw) {
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  PixelRays rays;
  rays.origin = Eigen::Vector3d(world.start_pose[0], world.start_pose[1], 1.1);
  rays.forward = rotation.col(0);
  rays.right = -rotation.col(1) / 160.0;
  rays.down = -rotation.col(2) / 160.0;
  rays.width = 320;
  rays.height = 240;
  rays.cx = 159.5;
  rays.cy = 119.5;
  return rays;
}

void BM_CastImage320x240_Office_Silhouettes(benchmark::State& state) {
  const World world = loadWorld(worldPath("office.ini"));
  RayCaster caster(world);
  double yaw = 0.0;
  for (auto _ : state) {
    yaw += 0.2;
    caster.cast(officeView(world, yaw));
    benchmark::DoNotOptimize(caster.hit(160, 120).t);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * 320 * 240);
}

// The peer: every pixel's ray tested against every solid.
void BM_CastImage320x240_Office_EverySolid(benchmark::State& state) {
  const World world = loadWorld(worldPath("office.ini"));
  double yaw = 0.0;
  for (auto _ : state) {
    yaw += 0.2;
    const PixelRays rays = officeView(world, yaw);
    for (int y = 0; y < rays.height; ++y) {
      for (int x = 0; x < rays.width; ++x) {
        const Ray ray = rays.ray(x, y);
        double nearest = std::min(intersectHorizontalPlane(0.0, ray, kNoHit),
                                  intersectHorizontalPlane(world.ceiling_height, ray, kNoHit));
        for (const Solid& solid : world.solids) {
          int face = 0;
          nearest = std::min(nearest, intersectSolid(solid, ray, nearest, &face));
        }
        benchmark::DoNotOptimize(nearest);
      }
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * 320 * 240);
}

BENCHMARK(BM_CastImage320x240_Office_Silhouettes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CastImage320x240_Office_EverySolid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_Office)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_TableRoom)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_PicketFence)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular320x240_Office)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
