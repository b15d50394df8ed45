// Rendering cost of one trinocular frame (the reference and two secondary cameras plus the true
// disparity) at the paper's 160 x 120 (section 3.3) and at 320 x 240, in the bundled worlds.
#include <benchmark/benchmark.h>

#include <string>

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
  double time = 0.0;
  for (auto _ : state) {
    // Turn on the spot so every frame sees a different part of the world.
    pose.phi_incr(0.2);
    time += 0.2;
    benchmark::DoNotOptimize(renderer.render(pose, time));
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

BENCHMARK(BM_RenderTrinocular160x120_Office)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_TableRoom)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular160x120_PicketFence)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderTrinocular320x240_Office)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
