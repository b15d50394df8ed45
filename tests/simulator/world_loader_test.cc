#include "simulator/world_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world_text.h"

namespace stereonav {
namespace {

// The error message for loading `text`, or "" if it loads.
std::string loadError(const std::string& text) {
  try {
    worldFromText(text);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(WorldLoader, UnknownKeyNamesFileSectionKeyAndNearestKnownKey) {
  const std::string message = loadError("[box.desk]\ncenter = 1 2\nsise = 1 1\n");
  EXPECT_NE(message.find("test.ini"), std::string::npos) << message;
  EXPECT_NE(message.find("[box.desk]"), std::string::npos) << message;
  EXPECT_NE(message.find("'sise'"), std::string::npos) << message;
  EXPECT_NE(message.find("'size'"), std::string::npos) << message;
}

TEST(WorldLoader, BadValuesNameTheirKey) {
  EXPECT_NE(loadError("[box.desk]\ncenter = 1 two\nsize = 1 1\n").find("[box.desk] center"), std::string::npos);
  EXPECT_NE(loadError("[box.desk]\ncenter = 1 2\nsize = 1\n").find("[box.desk] size"), std::string::npos);
  EXPECT_NE(loadError("[box.desk]\ncenter = 1 2\nsize = 1 1\nheight = -1\n").find("[box.desk] height"),
            std::string::npos);
  EXPECT_NE(loadError("[cylinder.pole]\ncenter = 1 2\ntexture = marble\n").find("[cylinder.pole] texture"),
            std::string::npos);
  EXPECT_NE(loadError("[texture.t]\ntype = plaid\n").find("[texture.t] type"), std::string::npos);
  EXPECT_NE(loadError("[wall.w]\npoints = 0 0; 1\n").find("[wall.w] points"), std::string::npos);
  EXPECT_NE(loadError("[box.b]\nsize = 1 1\n").find("[box.b] center: missing"), std::string::npos);
  EXPECT_NE(loadError("[world]\nfloor_texture = maybe\n").find("[world] floor_texture"), std::string::npos);
  EXPECT_NE(loadError("[sofa.s]\n").find("[sofa.s]"), std::string::npos);
}

TEST(WorldLoader, MissingFileIsNamed) {
  try {
    loadWorld("/nonexistent/world.ini");
    FAIL() << "loaded a missing file";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/world.ini"), std::string::npos);
  }
}

TEST(WorldLoader, TableIsATopSlabOnFourLegs) {
  const World world = worldFromText(
      "[table.t]\ncenter = 2 1\nsize = 1.2 0.8\nyaw_deg = 90\nheight = 0.75\ntop_thickness = 0.04\n"
      "leg_radius = 0.03\nleg_inset = 0.05\n");
  ASSERT_EQ(world.solids.size(), 5u);
  const Solid& top = world.solids[0];
  EXPECT_EQ(top.shape, Solid::Shape::kBox);
  EXPECT_DOUBLE_EQ(top.z_max, 0.75);
  EXPECT_NEAR(top.z_min, 0.71, 1e-12);
  // Turned by 90 degrees, the 1.2 m side runs along y: legs at x = 2 +- 0.32, y = 1 +- 0.52.
  for (size_t i = 1; i < 5; ++i) {
    const Solid& leg = world.solids[i];
    EXPECT_EQ(leg.shape, Solid::Shape::kCylinder);
    EXPECT_NEAR(std::abs(leg.x - 2.0), 0.4 - 0.05 - 0.03, 1e-12);
    EXPECT_NEAR(std::abs(leg.y - 1.0), 0.6 - 0.05 - 0.03, 1e-12);
    EXPECT_DOUBLE_EQ(leg.z_min, 0.0);
    EXPECT_NEAR(leg.z_max, 0.71, 1e-12);
  }
}

TEST(WorldLoader, PicketFenceHasEvenlySpacedIdenticalPickets) {
  const World world = worldFromText(
      "[picket_fence.f]\nfrom = 0 0\nto = 1 0\npicket_width = 0.05\ngap = 0.05\nheight = 1\n");
  // (1 + 0.05) / (0.05 + 0.05) = 10.5: ten pickets, centres 0.025 + 0.1 k.
  ASSERT_EQ(world.solids.size(), 10u);
  for (size_t k = 0; k < world.solids.size(); ++k) {
    EXPECT_NEAR(world.solids[k].x, 0.025 + 0.1 * k, 1e-12);
    EXPECT_DOUBLE_EQ(world.solids[k].half_x, 0.025);
    EXPECT_EQ(world.solids[k].texture_offset, world.solids[0].texture_offset);
  }
}

TEST(WorldLoader, FloorWithoutTextureIsPaint) {
  const World textured = worldFromText("[world]\nfloor_texture = true\n");
  const World plain = worldFromText("[world]\nfloor_texture = false\n");
  EXPECT_EQ(textured.textures[textured.floor_texture].kind, SurfaceTexture::Kind::kNoise);
  EXPECT_EQ(plain.textures[plain.floor_texture].kind, SurfaceTexture::Kind::kPaint);
}

TEST(WorldLoader, MovingObstacleLoopsAlongItsPath) {
  const World world = worldFromText("[moving.person]\npath = 0 0; 4 0; 4 3\nspeed = 1\nradius = 0.25\n");
  ASSERT_EQ(world.moving_obstacles.size(), 1u);
  const MovingObstacle& person = world.moving_obstacles[0];
  EXPECT_EQ(person.name, "moving.person");
  EXPECT_NEAR(person.at(2.0).x, 2.0, 1e-12);
  EXPECT_NEAR(person.at(5.0).x, 4.0, 1e-12);
  EXPECT_NEAR(person.at(5.0).y, 1.0, 1e-12);
  // The loop is 4 + 3 + 5 = 12 m long; back on the closing leg after 9.5 m: 2.5 m from the end.
  EXPECT_NEAR(person.at(9.5).x, 4.0 * 2.5 / 5.0, 1e-12);
  EXPECT_NEAR(person.at(9.5).y, 3.0 * 2.5 / 5.0, 1e-12);
  EXPECT_NEAR(person.at(12.0 + 2.0).x, 2.0, 1e-12);
}

TEST(WorldLoader, BundledWorldsLoad) {
  for (const char* name : {"office.ini", "table_room.ini", "picket_fence.ini"}) {
    SCOPED_TRACE(name);
    const World world = loadWorld(worldsDirectory() + "/" + name);
    EXPECT_GT(world.solids.size(), 4u);
    EXPECT_GT(world.bounds[2], world.bounds[0]);
  }
  const World office = loadWorld(worldsDirectory() + "/office.ini");
  EXPECT_NEAR(office.bounds[2] - office.bounds[0], 20.0, 0.5);
  EXPECT_NEAR(office.bounds[3] - office.bounds[1], 15.0, 0.5);
}

}  // namespace
}  // namespace stereonav
