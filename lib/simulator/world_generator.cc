#include "simulator/world_generator.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>
#include <tuple>

#include "simulator/ground_truth_map.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

constexpr double kWallThicknessM = 0.1;
constexpr double kCeilingHeightM = 2.6;
constexpr double kMinRoomSideM = 2.5;
// Furniture keeps this far from a door's centre, so the way through stays open on both sides.
constexpr double kDoorClearanceM = 1.2;
// A door keeps this far from where another wall meets its wall, so no wall closes it.
constexpr double kDoorToJunctionM = 0.45;

// Draws from std::mt19937's raw output only: the same numbers with every standard library.
class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}
  double uniform(double low, double high) {
    return low + (high - low) * (static_cast<double>(engine_()) / 4294967296.0);
  }
  int integer(int low, int high) {  // inclusive
    return low + static_cast<int>(engine_() % static_cast<unsigned>(high - low + 1));
  }
  bool chance(double probability) { return uniform(0.0, 1.0) < probability; }

 private:
  std::mt19937 engine_;
};

// A straight interior wall on a centre line: y = at from `from` to `to` (along_x), or x = at.
struct WallLine {
  bool along_x;
  double at, from, to;
  std::vector<double> junctions;  // where other walls meet it, along it
  std::vector<std::pair<double, double>> gaps;  // door openings between slab ends, along it
};

// Something standing in a room, with its footprint for spacing.
struct Furniture {
  FloorRect rect;
  std::string section;  // the world-file section, whole
};

class WorldBuilder {
 public:
  explicit WorldBuilder(unsigned seed) : random_(seed) { world_.seed = seed; }

  GeneratedWorld build() {
    const int kind = random_.integer(0, 2);
    if (kind == 0) apartment();
    if (kind == 1) office();
    if (kind == 2) hall();
    for (const WallLine& wall : walls_) addJunctions(wall);
    placeDoors();
    furnish();
    person();
    while (!writeAndCheckReachable() && !furniture_.empty()) furniture_.pop_back();
    world_.furniture = furniture_.size();
    return world_;
  }

 private:
  // --- the rooms ---
  void apartment() {
    world_.kind = "apartment";
    const double width = random_.uniform(8.0, 14.0), depth = random_.uniform(8.0, 12.0);
    world_.footprint = {0, 0, width, depth};
    world_.rooms = {world_.footprint};
    const int rooms = random_.integer(3, 6);
    while (static_cast<int>(world_.rooms.size()) < rooms && splitLargestRoom()) {
    }
    const FloorRect& largest = *std::max_element(world_.rooms.begin(), world_.rooms.end(), byArea);
    start(largest);
  }

  void office() {
    world_.kind = "office";
    const double length = random_.uniform(16.0, 30.0), depth = random_.uniform(10.0, 20.0);
    world_.footprint = {0, 0, length, depth};
    const double corridor = random_.uniform(1.6, 2.2);
    const double y0 = depth / 2 - corridor / 2 + random_.uniform(-1.0, 1.0);
    const FloorRect hallway{0, y0, length, y0 + corridor};
    world_.rooms = {hallway};
    // At most 11 rooms beside the corridor: rooms widen on long floors.
    const double min_width = std::max(3.0, 2.0 * length / 11.0);
    for (const auto& [side_y0, side_y1, wall_y] :
         {std::tuple{0.0, y0, y0}, std::tuple{y0 + corridor, depth, y0 + corridor}}) {
      walls_.push_back({true, wall_y, 0.0, length, {}, {}});
      const size_t corridor_wall = walls_.size() - 1;
      double x = 0.0;
      while (x < length - 0.01) {
        double width = random_.uniform(min_width, min_width + 2.5);
        if (length - (x + width) < min_width) width = length - x;
        world_.rooms.push_back({x, side_y0, x + width, side_y1});
        door_requests_.push_back({corridor_wall, x, x + width});
        if (x + width < length - 0.01) walls_.push_back({false, x + width, side_y0, side_y1, {}, {}});
        x += width;
      }
    }
    start(hallway);
  }

  void hall() {
    world_.kind = "hall";
    const double length = random_.uniform(14.0, 24.0), depth = random_.uniform(10.0, 16.0);
    world_.footprint = {0, 0, length, depth};
    const double strip = random_.uniform(3.5, 5.0);
    const FloorRect main{0, 0, length, depth - strip};
    world_.rooms = {main};
    walls_.push_back({true, depth - strip, 0.0, length, {}, {}});
    const int side_rooms = random_.integer(2, 4);
    const double width = length / side_rooms;
    for (int i = 0; i < side_rooms; ++i) {
      const double x0 = i * width, x1 = (i + 1) * width;
      world_.rooms.push_back({x0, depth - strip, x1, depth});
      door_requests_.push_back({0, x0, x1});
      if (i + 1 < side_rooms) walls_.push_back({false, x1, depth - strip, depth, {}, {}});
    }
    // Pillars down the hall.
    const int pillars = random_.integer(2, 4);
    for (int i = 0; i < pillars; ++i) {
      const double x = length * (i + 1) / (pillars + 1), y = (depth - strip) * 0.5 + random_.uniform(-1.5, 1.5);
      addFurniture({x - 0.25, y - 0.25, x + 0.25, y + 0.25},
                   cylinder("pillar", x, y, random_.uniform(0.15, 0.22), kCeilingHeightM, "concrete"), false);
    }
    start({main.x0, main.y0, main.x1, main.y0 + (main.depth()) * 0.3});
  }

  static bool byArea(const FloorRect& a, const FloorRect& b) {
    return a.width() * a.depth() < b.width() * b.depth();
  }

  // Splits the largest room that can take it across its longer side, the new wall with a door.
  bool splitLargestRoom() {
    std::vector<size_t> order(world_.rooms.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return byArea(world_.rooms[b], world_.rooms[a]); });
    for (size_t index : order) {
      const FloorRect room = world_.rooms[index];
      const bool across_x = room.width() >= room.depth();  // a wall at constant x
      const double side = across_x ? room.width() : room.depth();
      if (side < 2 * kMinRoomSideM) continue;
      const double share = random_.uniform(0.35, 0.65);
      const double cut = std::clamp(side * share, kMinRoomSideM, side - kMinRoomSideM);
      FloorRect first = room, second = room;
      if (across_x) {
        first.x1 = second.x0 = room.x0 + cut;
        walls_.push_back({false, room.x0 + cut, room.y0, room.y1, {}, {}});
      } else {
        first.y1 = second.y0 = room.y0 + cut;
        walls_.push_back({true, room.y0 + cut, room.x0, room.x1, {}, {}});
      }
      door_requests_.push_back({walls_.size() - 1, across_x ? room.y0 : room.x0, across_x ? room.y1 : room.x1});
      world_.rooms[index] = first;
      world_.rooms.push_back(second);
      return true;
    }
    return false;
  }

  void start(const FloorRect& room) {
    world_.start_x = 0.5 * (room.x0 + room.x1);
    world_.start_y = 0.5 * (room.y0 + room.y1);
    start_yaw_deg_ = 90.0 * random_.integer(0, 3);
  }

  // --- walls and doors ---
  // Records where `wall`'s ends meet the other walls.
  void addJunctions(const WallLine& wall) {
    for (WallLine& other : walls_) {
      if (&other == &wall || other.along_x == wall.along_x) continue;
      for (double end : {wall.from, wall.to}) {
        if (std::abs(end - other.at) < 1e-6 && wall.at > other.from - 1e-6 && wall.at < other.to + 1e-6) {
          other.junctions.push_back(wall.at);
        }
      }
    }
  }

  // One door per request, inside [from, to] of its wall, away from the wall's junctions.
  void placeDoors() {
    for (const DoorRequest& request : door_requests_) {
      WallLine& wall = walls_[request.wall];
      const double width = random_.uniform(kGeneratedDoorMinWidthM, kGeneratedDoorMaxWidthM);
      const double half = width / 2 + kWallThicknessM / 2;
      std::vector<double> candidates;
      for (double at = request.from + half + kDoorToJunctionM; at <= request.to - half - kDoorToJunctionM; at += 0.05) {
        const bool clear = std::all_of(wall.junctions.begin(), wall.junctions.end(),
                                       [&](double j) { return std::abs(j - at) > half + kDoorToJunctionM; });
        if (clear) candidates.push_back(at);
      }
      if (candidates.empty()) continue;  // a room too narrow for a door: the test would say so
      const double at = candidates[static_cast<size_t>(random_.integer(0, static_cast<int>(candidates.size()) - 1))];
      wall.gaps.push_back({at - half, at + half});
      world_.doors.push_back({wall.along_x ? at : wall.at, wall.along_x ? wall.at : at, wall.along_x, width});
    }
  }

  // --- furniture ---
  bool clearOfDoorsAndStart(const FloorRect& r, double door_clearance) const {
    const auto distance = [&](double x, double y) {
      const double dx = std::max({r.x0 - x, 0.0, x - r.x1}), dy = std::max({r.y0 - y, 0.0, y - r.y1});
      return std::hypot(dx, dy);
    };
    for (const GeneratedDoor& door : world_.doors) {
      if (distance(door.x, door.y) < door_clearance) return false;
    }
    return distance(world_.start_x, world_.start_y) > 1.0;
  }

  bool fits(const FloorRect& r) const {
    for (const Furniture& other : furniture_) {
      if (r.x0 < other.rect.x1 + 0.15 && r.x1 > other.rect.x0 - 0.15 && r.y0 < other.rect.y1 + 0.15 &&
          r.y1 > other.rect.y0 - 0.15) {
        return false;
      }
    }
    return clearOfDoorsAndStart(r, kDoorClearanceM);
  }

  void addFurniture(const FloorRect& rect, const std::string& section, bool check) {
    if (check && !fits(rect)) return;
    furniture_.push_back({rect, section});
  }

  std::string name(const std::string& kind) { return kind + "." + kind + "_" + std::to_string(++counter_); }

  std::string box(const std::string& kind, const FloorRect& r, double height, const std::string& texture) {
    std::ostringstream text;
    text << "[" << name("box") << "]  # " << kind << "\ncenter = " << 0.5 * (r.x0 + r.x1) << " "
         << 0.5 * (r.y0 + r.y1) << "\nsize = " << r.width() << " " << r.depth() << "\nheight = " << height
         << "\ntexture = " << texture << "\n\n";
    return text.str();
  }
  std::string cylinder(const std::string& kind, double x, double y, double radius, double height,
                       const std::string& texture) {
    std::ostringstream text;
    text << "[" << name("cylinder") << "]  # " << kind << "\ncenter = " << x << " " << y << "\nradius = " << radius
         << "\nheight = " << height << "\ntexture = " << texture << "\n\n";
    return text.str();
  }
  std::string table(const std::string& kind, const FloorRect& r, double height, double leg_radius,
                    const std::string& texture) {
    std::ostringstream text;
    text << "[" << name("table") << "]  # " << kind << "\ncenter = " << 0.5 * (r.x0 + r.x1) << " "
         << 0.5 * (r.y0 + r.y1) << "\nsize = " << r.width() << " " << r.depth() << "\nheight = " << height
         << "\nleg_radius = " << leg_radius << "\ntexture = " << texture << "\nleg_texture = steel\n\n";
    return text.str();
  }

  // A footprint of sx x sy in `room`, against one of its walls or anywhere inside.
  FloorRect placeIn(const FloorRect& room, double sx, double sy, bool against_wall) {
    if (random_.chance(0.5)) std::swap(sx, sy);
    const double inset = kWallThicknessM / 2 + 0.03;
    const FloorRect inner{room.x0 + inset, room.y0 + inset, room.x1 - inset, room.y1 - inset};
    double x0 = random_.uniform(inner.x0 + 0.3, std::max(inner.x0 + 0.3, inner.x1 - 0.3 - sx));
    double y0 = random_.uniform(inner.y0 + 0.3, std::max(inner.y0 + 0.3, inner.y1 - 0.3 - sy));
    if (against_wall) {
      switch (random_.integer(0, 3)) {
        case 0: x0 = inner.x0; break;
        case 1: x0 = inner.x1 - sx; break;
        case 2: y0 = inner.y0; break;
        default: y0 = inner.y1 - sy; break;
      }
    }
    FloorRect r{x0, y0, x0 + sx, y0 + sy};
    if (r.x1 > inner.x1 || r.y1 > inner.y1 || r.x0 < inner.x0 || r.y0 < inner.y0) r = {};
    return r;
  }

  void furnish() {
    for (const FloorRect& room : world_.rooms) {
      if (&room == &world_.rooms.front() && world_.kind == "office") continue;  // the corridor stays clear
      const size_t before = furniture_.size();
      const int items = std::min(8, static_cast<int>(room.width() * room.depth() / 7.0) + random_.integer(0, 2));
      for (int item = 0; item < items; ++item) {
        for (int attempt = 0; attempt < 30; ++attempt) {
          if (tryFurniture(room)) break;
        }
      }
      // What this room's furniture closes off goes again, newest first.
      while (furniture_.size() > before && !writeAndCheckReachable()) furniture_.pop_back();
    }
  }

  bool tryFurniture(const FloorRect& room) {
    const size_t before = furniture_.size();
    const int kind = random_.integer(0, 8);
    FloorRect r;
    std::string section;
    switch (kind) {
      case 0:  // table, top anywhere from coffee-table to bar height
        r = placeIn(room, random_.uniform(0.8, 1.6), random_.uniform(0.6, 1.0), false);
        section = table("table", r, random_.uniform(0.4, 0.8), 0.025, "laminate");
        break;
      case 1:  // desk against a wall
        r = placeIn(room, random_.uniform(1.2, 1.6), random_.uniform(0.6, 0.8), true);
        section = table("desk", r, random_.uniform(0.72, 0.76), 0.02, "laminate");
        break;
      case 2: {  // chair: a seat on four thin legs
        const double side = random_.uniform(0.42, 0.48);
        r = placeIn(room, side, side, false);
        section = table("chair", r, 0.45, 0.012, "fabric");
        break;
      }
      case 3:  // sofa
        r = placeIn(room, random_.uniform(1.8, 2.2), random_.uniform(0.8, 0.9), true);
        section = box("sofa", r, 0.8, "fabric");
        break;
      case 4:  // bed
        r = placeIn(room, 2.0, random_.uniform(1.4, 1.8), true);
        section = box("bed", r, 0.5, "fabric");
        break;
      case 5:  // cabinet
        r = placeIn(room, random_.uniform(0.4, 0.6), random_.uniform(0.8, 1.2), true);
        section = box("cabinet", r, random_.uniform(1.0, 2.0), random_.chance(0.5) ? "wood" : "paint_white");
        break;
      case 6: {  // thin pole, 2-5 cm
        const double radius = random_.uniform(0.01, 0.025);
        r = placeIn(room, 0.1, 0.1, false);
        section = cylinder("pole", 0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1), radius, kCeilingHeightM, "steel");
        break;
      }
      default: {  // plant
        const double radius = random_.uniform(0.2, 0.3);
        r = placeIn(room, 2 * radius, 2 * radius, false);
        section = cylinder("plant", 0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1), radius, random_.uniform(0.6, 1.2), "leaves");
        break;
      }
    }
    if (r.width() <= 0.0) return false;
    addFurniture(r, section, true);
    return furniture_.size() > before;
  }

  // A person walking the length of the largest room, in some worlds.
  void person() {
    if (!random_.chance(0.4)) return;
    const FloorRect& room = *std::max_element(world_.rooms.begin(), world_.rooms.end(), byArea);
    const bool along_x = room.width() >= room.depth();
    const double cx = 0.5 * (room.x0 + room.x1), cy = 0.5 * (room.y0 + room.y1);
    std::ostringstream text;
    text << "[moving.person]\npath = ";
    if (along_x) {
      text << room.x0 + 0.8 << " " << cy << "; " << room.x1 - 0.8 << " " << cy;
    } else {
      text << cx << " " << room.y0 + 0.8 << "; " << cx << " " << room.y1 - 0.8;
    }
    text << "\nspeed = " << random_.uniform(0.4, 0.8) << "\nradius = 0.25\nheight = 1.7\ntexture = clothes\n\n";
    person_ = text.str();
    world_.moving_person = true;
  }

  // --- the file ---
  std::string wallTexture(Random& pick, bool flat) {
    if (flat) return "paint_white";
    const double u = pick.uniform(0.0, 1.0);
    if (u < 0.08) return "stripes";
    if (u < 0.16) return "poster";
    return "plaster_" + std::to_string(pick.integer(1, 3));
  }

  std::string text() {
    std::ostringstream out;
    out << std::setprecision(4) << std::fixed;
    const FloorRect& f = world_.footprint;
    out << "# A generated " << world_.kind << " (stereonav generate --seed " << world_.seed
        << "): " << world_.rooms.size() << " rooms and corridors, " << world_.doors.size()
        << " doors. An ordinary world file (docs/worlds.md): edit it and rerun.\n\n";
    out << "[world]\nbounds = " << f.x0 - 0.2 << " " << f.y0 - 0.2 << " " << f.x1 + 0.2 << " " << f.y1 + 0.2
        << "\nstart_pose = " << world_.start_x << " " << world_.start_y << " " << start_yaw_deg_
        << "\nwall_thickness = " << kWallThicknessM << "\nfloor = floor_tiles\nceiling_height = "
        << kCeilingHeightM << "\nceiling = ceiling_tiles\n\n";
    out << kTextures;
    // Every wall section, exterior sides first, then the interior walls cut at their doors.
    std::vector<std::pair<cv::Point2d, cv::Point2d>> sections{
        {{f.x0, f.y0}, {f.x1, f.y0}}, {{f.x1, f.y0}, {f.x1, f.y1}}, {{f.x1, f.y1}, {f.x0, f.y1}}, {{f.x0, f.y1}, {f.x0, f.y0}}};
    for (WallLine& wall : walls_) {
      std::sort(wall.gaps.begin(), wall.gaps.end());
      double from = wall.from;
      for (const auto& [gap_from, gap_to] : wall.gaps) {
        sections.push_back(segment(wall, from, gap_from));
        from = gap_to;
      }
      sections.push_back(segment(wall, from, wall.to));
    }
    // The flat share is drawn once per world, and which sections are flat from their own stream,
    // so the furniture does not change with it.
    Random pick(world_.seed * 7919u + 17u);
    const double flat_share = pick.uniform(0.2, 0.4);
    const double count = static_cast<double>(sections.size());
    const size_t flat = static_cast<size_t>(
        std::clamp(std::round(flat_share * count), std::ceil(0.2 * count), std::floor(0.4 * count)));
    std::vector<size_t> order(sections.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[static_cast<size_t>(pick.integer(0, static_cast<int>(i) - 1))]);
    std::vector<bool> is_flat(sections.size(), false);
    for (size_t i = 0; i < flat; ++i) is_flat[order[i]] = true;
    for (size_t i = 0; i < sections.size(); ++i) {
      out << "[wall.w" << i << "]\npoints = " << sections[i].first.x << " " << sections[i].first.y << "; "
          << sections[i].second.x << " " << sections[i].second.y << "\ntexture = " << wallTexture(pick, is_flat[i])
          << "\n\n";
    }
    world_.wall_sections = sections.size();
    world_.flat_wall_sections = flat;
    for (const Furniture& item : furniture_) out << item.section;
    out << person_;
    return out.str();
  }

  static std::pair<cv::Point2d, cv::Point2d> segment(const WallLine& wall, double from, double to) {
    if (wall.along_x) return {{from, wall.at}, {to, wall.at}};
    return {{wall.at, from}, {wall.at, to}};
  }

  // Writes the file and checks, on its ground-truth map, that every room has floor a robot of
  // kGeneratedRobotRadiusM reaches from the start.
  bool writeAndCheckReachable() {
    world_.ini_text = text();
    mrpt::config::CConfigFileMemory config(world_.ini_text);
    GroundTruthMapOptions options;
    const GroundTruthMap truth(loadWorld(config, "generated world"), options);
    cv::Mat1b blocked(truth.height(), truth.width());
    for (int iy = 0; iy < truth.height(); ++iy) {
      for (int ix = 0; ix < truth.width(); ++ix) {
        blocked(iy, ix) = truth.cell(ix, iy) == GroundTruthMap::kFree ? 0 : 255;
      }
    }
    const int radius = static_cast<int>(std::ceil(kGeneratedRobotRadiusM / truth.resolution()));
    cv::dilate(blocked, blocked, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1}));
    const auto cellOf = [&](double x, double y) {
      return cv::Point(static_cast<int>((x - truth.xMin()) / truth.resolution()),
                       static_cast<int>((y - truth.yMin()) / truth.resolution()));
    };
    const cv::Point start = cellOf(world_.start_x, world_.start_y);
    if (blocked(start) != 0) return false;
    cv::floodFill(blocked, start, 128);
    for (const FloorRect& room : world_.rooms) {
      const cv::Point a = cellOf(room.x0, room.y0), b = cellOf(room.x1, room.y1);
      const cv::Mat1b inside = blocked(cv::Range(a.y, b.y), cv::Range(a.x, b.x));
      if (cv::countNonZero(inside == 128) == 0) return false;
    }
    return true;
  }

  struct DoorRequest {
    size_t wall;
    double from, to;  // the span of the wall the door must open into
  };

  static constexpr const char* kTextures =
      "[texture.floor_tiles]\ntype = noise\nmean = 0.5\ncontrast = 0.3\nscales_m = 0.6 0.15 0.04\nseed = 21\n\n"
      "[texture.ceiling_tiles]\ntype = noise\nmean = 0.85\ncontrast = 0.1\nscales_m = 0.6 0.15\nseed = 13\n\n"
      "[texture.plaster_1]\ntype = noise\nmean = 0.6\ncontrast = 0.25\nscales_m = 0.5 0.12 0.03\nseed = 3\n\n"
      "[texture.plaster_2]\ntype = noise\nmean = 0.5\ncontrast = 0.3\nscales_m = 0.4 0.1 0.025\nseed = 5\n\n"
      "[texture.plaster_3]\ntype = noise\nmean = 0.7\ncontrast = 0.2\nscales_m = 0.3 0.08\nseed = 9\n\n"
      "[texture.paint_white]\n# Flat paint: nothing for stereo to match.\ntype = paint\nmean = 0.8\n\n"
      "[texture.stripes]\ntype = stripes\nmean = 0.5\ncontrast = 0.35\nperiod_m = 0.12\n\n"
      "[texture.poster]\ntype = poster\nmean = 0.75\ncontrast = 0.3\nrect = -0.5 0.9 0.5 1.7\n\n"
      "[texture.laminate]\ntype = noise\nmean = 0.7\ncontrast = 0.12\nscales_m = 0.2 0.05\nseed = 23\n\n"
      "[texture.wood]\ntype = noise\nmean = 0.45\ncontrast = 0.25\nscales_m = 0.3 0.05\nseed = 31\n\n"
      "[texture.steel]\ntype = noise\nmean = 0.3\ncontrast = 0.15\nscales_m = 0.1 0.02\nseed = 7\n\n"
      "[texture.fabric]\ntype = noise\nmean = 0.35\ncontrast = 0.35\nscales_m = 0.2 0.05\nseed = 29\n\n"
      "[texture.leaves]\ntype = noise\nmean = 0.3\ncontrast = 0.4\nscales_m = 0.08 0.02\nseed = 37\n\n"
      "[texture.concrete]\ntype = noise\nmean = 0.55\ncontrast = 0.2\nscales_m = 0.3 0.06\nseed = 41\n\n"
      "[texture.clothes]\ntype = noise\nmean = 0.4\ncontrast = 0.3\nscales_m = 0.15 0.04\nseed = 43\n\n";

  Random random_;
  GeneratedWorld world_;
  std::vector<WallLine> walls_;
  std::vector<DoorRequest> door_requests_;
  std::vector<Furniture> furniture_;
  std::string person_;
  double start_yaw_deg_ = 0.0;
  int counter_ = 0;
};

}  // namespace

GeneratedWorld generateWorld(unsigned seed) { return WorldBuilder(seed).build(); }

}  // namespace stereonav
