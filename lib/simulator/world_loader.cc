#include "simulator/world_loader.h"

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <utility>

#include "common/ini_section.h"
#include "occupancy_grid/ros_map.h"
#include "simulator/number_list.h"

namespace stereonav {
namespace {

constexpr const char* kDefaultTexture = "default";

// Cells [row_begin, row_end) x [col_begin, col_end) of a map.
struct CellRectangle {
  int row_begin, row_end, col_begin, col_end;
};

// The occupied cells of `plan` as rectangles: each row's runs of occupied cells, a run merged
// with the rectangle above it when that one spans exactly the same columns.
std::vector<CellRectangle> occupiedRectangles(const RosMap& plan) {
  std::vector<CellRectangle> done;
  std::map<std::pair<int, int>, CellRectangle> open;  // by (col_begin, col_end)
  for (int row = 0; row < plan.height(); ++row) {
    std::map<std::pair<int, int>, CellRectangle> continued;
    for (int col = 0; col < plan.width();) {
      if (plan.cell(col, row) != CellClass::kOccupied) {
        ++col;
        continue;
      }
      const int begin = col;
      while (col < plan.width() && plan.cell(col, row) == CellClass::kOccupied) ++col;
      const auto above = open.find({begin, col});
      CellRectangle rectangle = above != open.end() ? above->second : CellRectangle{row, row, begin, col};
      if (above != open.end()) open.erase(above);
      rectangle.row_end = row + 1;
      continued[{begin, col}] = rectangle;
    }
    for (const auto& entry : open) done.push_back(entry.second);
    open = std::move(continued);
  }
  for (const auto& entry : open) done.push_back(entry.second);
  return done;
}

class WorldBuilder {
 public:
  // `directory`: where file names in the world (a floor plan's map) are relative to.
  WorldBuilder(const mrpt::config::CConfigFileBase& config, std::string directory)
      : config_(config), directory_(std::move(directory)) {}

  World build() {
    std::vector<std::string> sections;
    config_.getAllSections(sections);
    defineTexture(kDefaultTexture, SurfaceTexture{});
    for (const auto& name : sections) {
      if (kindOf(name) == "texture") {
        IniSection section(config_, name);
        defineTexture(name.substr(name.find('.') + 1), loadSurfaceTexture(section));
        section.rejectUnknownKeys();
      }
    }
    IniSection world_section(config_, "world");
    loadWorldSection(world_section);
    for (const auto& name : sections) {
      const std::string kind = kindOf(name);
      if (name == "world" || kind == "texture") continue;
      IniSection section(config_, name);
      if (kind == "wall") {
        addWall(section);
      } else if (kind == "box") {
        addBox(section);
      } else if (kind == "cylinder") {
        addCylinder(section);
      } else if (kind == "table") {
        addTable(section);
      } else if (kind == "picket_fence") {
        addPicketFence(section);
      } else if (kind == "moving") {
        addMovingObstacle(section);
      } else if (kind == "floor_plan") {
        addFloorPlan(section);
      } else {
        throw ConfigError("[" + name +
                          "]: unknown section; expected [world] or [<kind>.<name>] with kind "
                          "texture, wall, box, cylinder, table, picket_fence, moving or floor_plan");
      }
      section.rejectUnknownKeys();
    }
    // Every solid gets its own patch of texture, except fence pickets, which are meant to look
    // identical.
    for (size_t i = 0; i < world_.solids.size(); ++i) {
      if (!identical_texture_[i]) world_.solids[i].texture_offset = 37.1 * static_cast<double>(i);
    }
    if (!explicit_bounds_) computeBounds();
    return world_;
  }

 private:
  static std::string kindOf(const std::string& section_name) {
    const size_t dot = section_name.find('.');
    return dot == std::string::npos ? section_name : section_name.substr(0, dot);
  }

  static std::string where(const IniSection& section, const std::string& key) {
    return "[" + section.name() + "] " + key;
  }

  [[noreturn]] static void fail(const IniSection& section, const std::string& key, const std::string& why) {
    throw ConfigError(where(section, key) + ": " + why);
  }

  // Declares every key a kind of section understands before any is read, so that a misspelt
  // required key is reported as the misspelling, not as a missing key.
  static void acceptOnly(IniSection& section, std::initializer_list<const char*> keys) {
    for (const char* key : keys) section.getString(key, "");
    section.rejectUnknownKeys();
  }

  void defineTexture(const std::string& name, const SurfaceTexture& texture) {
    const auto known = texture_index_.find(name);
    if (known != texture_index_.end()) {
      world_.textures[known->second] = texture;
      return;
    }
    texture_index_[name] = static_cast<int>(world_.textures.size());
    world_.textures.push_back(texture);
    world_.texture_names.push_back(name);
  }

  int textureOf(IniSection& section, const std::string& key) {
    const std::string name = section.getString(key, kDefaultTexture);
    const auto known = texture_index_.find(name);
    if (known == texture_index_.end()) {
      fail(section, key, "no section [texture." + name + "] defines texture '" + name + "'");
    }
    return known->second;
  }

  // Lengths, heights and coordinates are bounded by [world] max_extent_m, which bounds every
  // size derived from the world (ground-truth maps, texture lookups, fence pickets).
  double positive(IniSection& section, const std::string& key, double default_value) {
    const double value = section.getPositive(key, default_value);
    checkExtent(section, key, value);
    return value;
  }

  double nonNegative(IniSection& section, const std::string& key, double default_value) {
    const double value = section.getNonNegative(key, default_value);
    checkExtent(section, key, value);
    return value;
  }

  double degrees(IniSection& section, const std::string& key) {
    return mrpt::DEG2RAD(section.getDouble(key, 0.0, -3600.0, 3600.0));
  }

  void checkExtent(const IniSection& section, const std::string& key, double value) const {
    if (!(std::abs(value) <= max_extent_m_)) {
      char why[160];
      std::snprintf(why, sizeof why, "%g is beyond [world] max_extent_m = %g m (raise it for a larger world)",
                    value, max_extent_m_);
      fail(section, key, why);
    }
  }

  std::vector<double> numbers(IniSection& section, const std::string& key, int count) {
    if (!section.has(key)) fail(section, key, "missing");
    const auto values = parseNumberList(section.getString(key, ""), where(section, key), count);
    for (double value : values) checkExtent(section, key, value);
    return values;
  }

  std::vector<Point2> points(IniSection& section, const std::string& key, size_t minimum) {
    if (!section.has(key)) fail(section, key, "missing");
    const auto list = parsePointList(section.getString(key, ""), where(section, key), minimum);
    if (list.size() > kMaxPoints) fail(section, key, "more than " + std::to_string(kMaxPoints) + " points");
    for (const Point2& point : list) {
      checkExtent(section, key, point.x);
      checkExtent(section, key, point.y);
    }
    return list;
  }

  void addSolid(const IniSection& section, const Solid& solid, bool identical_texture = false) {
    world_.solids.push_back(solid);
    world_.solid_sections.push_back(section.name());
    identical_texture_.push_back(identical_texture);
  }

  void loadWorldSection(IniSection& section) {
    max_extent_m_ = section.getDouble("max_extent_m", max_extent_m_, 1.0, 1e6);
    if (section.has("bounds")) {
      const auto b = numbers(section, "bounds", 4);
      if (b[2] <= b[0] || b[3] <= b[1]) fail(section, "bounds", "expected x_min y_min x_max y_max");
      std::copy(b.begin(), b.end(), world_.bounds);
      explicit_bounds_ = true;
    }
    if (section.has("start_pose")) {
      const auto pose = parseNumberList(section.getString("start_pose", ""), where(section, "start_pose"), 3);
      checkExtent(section, "start_pose", pose[0]);
      checkExtent(section, "start_pose", pose[1]);
      world_.start_pose[0] = pose[0];
      world_.start_pose[1] = pose[1];
      world_.start_pose[2] = mrpt::DEG2RAD(pose[2]);
    }
    wall_thickness_ = positive(section, "wall_thickness", wall_thickness_);
    const bool textured_floor = section.getBool("floor_texture", true);
    world_.floor_texture = textureOf(section, "floor");
    if (!textured_floor) {
      SurfaceTexture paint;
      paint.kind = SurfaceTexture::Kind::kPaint;
      paint.mean = world_.textures[world_.floor_texture].mean;
      world_.floor_texture = static_cast<int>(world_.textures.size());
      world_.textures.push_back(paint);
    }
    world_.ceiling_height = nonNegative(section, "ceiling_height", 0.0);
    world_.ceiling_texture = textureOf(section, "ceiling");
    world_.lighting_change = section.getDouble("lighting_change", 0.0, 0.0, 0.999);
    world_.lighting_period_s = section.getPositive("lighting_period_s", world_.lighting_period_s, 1e6);
    section.rejectUnknownKeys();
  }

  void addWall(IniSection& section) {
    acceptOnly(section, {"points", "height", "thickness", "texture"});
    const auto corners = points(section, "points", 2);
    const double height = positive(section, "height", 2.5);
    const double thickness = positive(section, "thickness", wall_thickness_);
    const int texture = textureOf(section, "texture");
    for (size_t i = 0; i + 1 < corners.size(); ++i) {
      const Point2& a = corners[i];
      const Point2& b = corners[i + 1];
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      if (length <= 0.0) fail(section, "points", "two consecutive points coincide");
      // Each slab runs half a thickness past its end points, so corners close.
      addSolid(section, Solid::box((a.x + b.x) / 2, (a.y + b.y) / 2, length + thickness, thickness,
                                   std::atan2(b.y - a.y, b.x - a.x), 0.0, height, texture));
    }
  }

  void addBox(IniSection& section) {
    acceptOnly(section, {"center", "size", "yaw_deg", "z", "height", "texture"});
    const auto center = numbers(section, "center", 2);
    const auto size = numbers(section, "size", 2);
    if (!(size[0] > 0.0 && size[1] > 0.0)) fail(section, "size", "must be positive");
    const double yaw = degrees(section, "yaw_deg");
    const double z = nonNegative(section, "z", 0.0);
    const double height = positive(section, "height", 1.0);
    addSolid(section,
             Solid::box(center[0], center[1], size[0], size[1], yaw, z, z + height, textureOf(section, "texture")));
  }

  // A ROS map_server floor plan: its occupied cells become walls `height` tall, as boxes over
  // rectangles of occupied cells (a run along a row, continued over the rows below it while the
  // same run repeats), so a straight wall is one box. Each box gets `flat_texture` with
  // probability `flat_share` (drawn from `seed`): walls that stereo cannot match.
  void addFloorPlan(IniSection& section) {
    acceptOnly(section, {"map", "height", "texture", "flat_share", "flat_texture", "seed"});
    const std::string map_file = section.getString("map", "");
    if (map_file.empty()) fail(section, "map", "missing: the floor plan's map_server YAML");
    const RosMap plan = loadFloorPlanMap(section, map_file);
    const double height = positive(section, "height", 2.5);
    const int texture = textureOf(section, "texture");
    const double flat_share = section.getDouble("flat_share", 0.0, 0.0, 1.0);
    if (flat_share > 0.0 && !section.has("flat_texture")) {
      fail(section, "flat_texture", "missing: flat_share > 0 needs a [texture.<name>] for the flat walls");
    }
    const int flat_texture = textureOf(section, "flat_texture");
    std::mt19937 random(static_cast<std::mt19937::result_type>(section.getInt("seed", 1, 0, 1 << 30)));
    std::uniform_real_distribution<double> draw(0.0, 1.0);
    for (const CellRectangle& cells : occupiedRectangles(plan)) {
      const double r = plan.resolution();
      addSolid(section, Solid::box(plan.xMin() + r * (cells.col_begin + cells.col_end) / 2.0,
                                   plan.yMin() + r * (cells.row_begin + cells.row_end) / 2.0,
                                   r * (cells.col_end - cells.col_begin), r * (cells.row_end - cells.row_begin), 0.0,
                                   0.0, height, draw(random) < flat_share ? flat_texture : texture));
    }
  }

  RosMap loadFloorPlanMap(const IniSection& section, const std::string& map_file) const {
    const std::filesystem::path path = std::filesystem::path(directory_) / map_file;
    std::optional<RosMap> plan;
    try {
      plan.emplace(loadRosMap(path.string()));
    } catch (const std::runtime_error& error) {
      fail(section, "map", error.what());
    }
    checkExtent(section, "map", plan->xMin());
    checkExtent(section, "map", plan->yMin());
    checkExtent(section, "map", plan->xMin() + plan->resolution() * plan->width());
    checkExtent(section, "map", plan->yMin() + plan->resolution() * plan->height());
    return *plan;
  }

  void addCylinder(IniSection& section) {
    acceptOnly(section, {"center", "radius", "z", "height", "texture"});
    const auto center = numbers(section, "center", 2);
    const double radius = positive(section, "radius", 0.1);
    const double z = nonNegative(section, "z", 0.0);
    const double height = positive(section, "height", 1.0);
    addSolid(section, Solid::cylinder(center[0], center[1], radius, z, z + height, textureOf(section, "texture")));
  }

  void addTable(IniSection& section) {
    acceptOnly(section, {"center", "size", "yaw_deg", "height", "top_thickness", "leg_radius", "leg_inset",
                         "texture", "leg_texture"});
    const auto center = numbers(section, "center", 2);
    const auto size = numbers(section, "size", 2);
    if (!(size[0] > 0.0 && size[1] > 0.0)) fail(section, "size", "must be positive");
    const double yaw = degrees(section, "yaw_deg");
    const double height = positive(section, "height", 0.72);
    const double top_thickness = positive(section, "top_thickness", 0.03);
    const double leg_radius = positive(section, "leg_radius", 0.02);
    const double leg_inset = nonNegative(section, "leg_inset", 0.05);
    const int texture = textureOf(section, "texture");
    const int leg_texture = section.has("leg_texture") ? textureOf(section, "leg_texture") : texture;
    if (top_thickness >= height) fail(section, "top_thickness", "must be less than height");
    if (leg_inset + leg_radius > std::min(size[0], size[1]) / 2) {
      fail(section, "leg_inset", "legs would stand outside the top");
    }
    const double bottom = height - top_thickness;
    addSolid(section, Solid::box(center[0], center[1], size[0], size[1], yaw, bottom, height, texture));
    const double leg_x = size[0] / 2 - leg_inset - leg_radius;
    const double leg_y = size[1] / 2 - leg_inset - leg_radius;
    for (int sx : {-1, 1}) {
      for (int sy : {-1, 1}) {
        const double lx = sx * leg_x;
        const double ly = sy * leg_y;
        addSolid(section, Solid::cylinder(center[0] + std::cos(yaw) * lx - std::sin(yaw) * ly,
                                          center[1] + std::sin(yaw) * lx + std::cos(yaw) * ly, leg_radius, 0.0, bottom,
                                          leg_texture));
      }
    }
  }

  void addPicketFence(IniSection& section) {
    acceptOnly(section, {"from", "to", "picket_width", "gap", "height", "thickness", "rail_size",
                         "rail_heights", "texture"});
    const auto from = numbers(section, "from", 2);
    const auto to = numbers(section, "to", 2);
    const double width = positive(section, "picket_width", 0.05);
    const double gap = positive(section, "gap", 0.07);
    const double height = positive(section, "height", 1.0);
    const double thickness = positive(section, "thickness", 0.02);
    const double rail_size = positive(section, "rail_size", 0.05);
    const std::vector<double> rails =
        parseNumberList(section.getString("rail_heights", ""), where(section, "rail_heights"));
    const int texture = textureOf(section, "texture");
    const double length = std::hypot(to[0] - from[0], to[1] - from[1]);
    if (length < width) fail(section, "to", "the fence is shorter than one picket");
    const double ux = (to[0] - from[0]) / length;
    const double uy = (to[1] - from[1]) / length;
    const double yaw = std::atan2(uy, ux);
    const double picket_count = std::floor((length + gap) / (width + gap));
    if (picket_count > kMaxPoints) {
      fail(section, "picket_width", "more than " + std::to_string(kMaxPoints) + " pickets; widen them or the gap");
    }
    const int pickets = static_cast<int>(picket_count);
    for (int i = 0; i < pickets; ++i) {
      const double s = width / 2 + i * (width + gap);
      addSolid(section, Solid::box(from[0] + ux * s, from[1] + uy * s, width, thickness, yaw, 0.0, height, texture),
               true);
    }
    for (double rail : rails) {
      if (rail - rail_size / 2 < 0.0 || rail + rail_size / 2 > height) {
        fail(section, "rail_heights", "rails must lie within the fence's height");
      }
      // Rails sit behind the pickets (on the side of the fence's left normal).
      const double behind = thickness;
      addSolid(section, Solid::box((from[0] + to[0]) / 2 - uy * behind, (from[1] + to[1]) / 2 + ux * behind, length,
                                   thickness, yaw, rail - rail_size / 2, rail + rail_size / 2, texture));
    }
  }

  void addMovingObstacle(IniSection& section) {
    acceptOnly(section, {"shape", "radius", "size", "yaw_deg", "height", "path", "speed", "texture"});
    MovingObstacle obstacle;
    obstacle.name = section.name();
    obstacle.path = points(section, "path", 1);
    obstacle.speed_mps = nonNegative(section, "speed", 0.5);
    const std::string shape = section.getString("shape", "cylinder");
    const double height = positive(section, "height", 1.7);
    const int texture = textureOf(section, "texture");
    const Point2& start = obstacle.path.front();
    if (shape == "box") {
      const auto size = numbers(section, "size", 2);
      if (!(size[0] > 0.0 && size[1] > 0.0)) fail(section, "size", "must be positive");
      obstacle.solid = Solid::box(start.x, start.y, size[0], size[1],
                                  degrees(section, "yaw_deg"), 0.0, height, texture);
    } else if (shape == "cylinder") {
      obstacle.solid = Solid::cylinder(start.x, start.y, positive(section, "radius", 0.25), 0.0, height, texture);
    } else {
      fail(section, "shape", "expected box or cylinder, got '" + shape + "'");
    }
    obstacle.solid.texture_offset = 53.7 * static_cast<double>(world_.moving_obstacles.size() + 1);
    world_.moving_obstacles.push_back(obstacle);
  }

  void computeBounds() {
    bool first = true;
    FloorExtent all{0.0, 0.0, 0.0, 0.0};
    const auto include = [&](const FloorExtent& e) {
      all = first ? e
                  : FloorExtent{std::min(all.x_min, e.x_min), std::min(all.y_min, e.y_min),
                                std::max(all.x_max, e.x_max), std::max(all.y_max, e.y_max)};
      first = false;
    };
    for (const auto& solid : world_.solids) include(solid.floorExtent());
    for (const auto& obstacle : world_.moving_obstacles) {
      for (const auto& point : obstacle.path) {
        Solid placed = obstacle.solid;
        placed.x = point.x;
        placed.y = point.y;
        include(placed.floorExtent());
      }
    }
    include({world_.start_pose[0], world_.start_pose[1], world_.start_pose[0], world_.start_pose[1]});
    world_.bounds[0] = all.x_min;
    world_.bounds[1] = all.y_min;
    world_.bounds[2] = all.x_max;
    world_.bounds[3] = all.y_max;
  }

  const mrpt::config::CConfigFileBase& config_;
  std::string directory_;
  World world_;
  std::map<std::string, int> texture_index_;
  std::vector<bool> identical_texture_;
  double wall_thickness_ = 0.1;
  double max_extent_m_ = 1000.0;
  // Bound on the points of one list and the pickets of one fence.
  static constexpr size_t kMaxPoints = 10000;
  bool explicit_bounds_ = false;
};

}  // namespace

World loadWorld(const mrpt::config::CConfigFileBase& config, const std::string& file_name) {
  try {
    return WorldBuilder(config, std::filesystem::path(file_name).parent_path().string()).build();
  } catch (const ConfigError& error) {
    throw ConfigError(file_name + ": " + error.what());
  }
}

World loadWorld(const std::string& path) {
  return loadWorld(readConfigFile(path), path);
}

}  // namespace stereonav
