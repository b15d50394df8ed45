#include "simulator/ray_intersection.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <random>
#include <string>

#include "simulator/moving_traffic.h"
#include "simulator/ray_caster.h"
#include "simulator/world_generator.h"
#include "world_text.h"

namespace stereonav {
namespace {

Ray rayFrom(double ox, double oy, double oz, double dx, double dy, double dz) {
  return {Eigen::Vector3d(ox, oy, oz), Eigen::Vector3d(dx, dy, dz)};
}

// The hit of one ray, cast as the single pixel of an image looking along it.
RayHit castOne(RayCaster& caster, const Ray& ray) {
  PixelRays rays;
  rays.origin = ray.origin;
  rays.forward = ray.direction;
  rays.right = ray.direction.unitOrthogonal();
  rays.down = ray.direction.cross(rays.right).normalized();
  caster.cast(rays);
  return caster.hit(0, 0);
}

TEST(RayIntersection, AxisAlignedBoxIsEnteredThroughTheNearFace) {
  const Solid box = Solid::box(5.0, 0.0, 2.0, 2.0, 0.0, 0.0, 1.0, 0);
  int face = -1;
  const Ray ray = rayFrom(0.0, 0.0, 0.5, 1.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(intersectSolid(box, ray, kNoHit, &face), 4.0);
  EXPECT_EQ(face, kFaceMinusX);
  const SurfacePoint point = surfaceOfSolid(box, face, ray, 4.0);
  EXPECT_NEAR((point.normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((point.position - Eigen::Vector3d(4, 0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(point.v, 0.5);  // side faces: v is the height
}

TEST(RayIntersection, RotatedBoxCornerAtHalfDiagonal) {
  // A 2 x 2 box turned by 45 degrees has a corner at x = -sqrt(2) on the x axis.
  const Solid box = Solid::box(0.0, 0.0, 2.0, 2.0, mrpt::DEG2RAD(45.0), 0.0, 1.0, 0);
  int face = -1;
  EXPECT_NEAR(intersectSolid(box, rayFrom(-5.0, 0.0, 0.5, 1.0, 0.0, 0.0), kNoHit, &face),
              5.0 - std::sqrt(2.0), 1e-12);
  // Through the middle of a face: at 45 degrees the face's centre is at distance 1 along (1, 1).
  const double t = intersectSolid(box, rayFrom(-3.0, -3.0, 0.5, 1.0, 1.0, 0.0), kNoHit, &face);
  EXPECT_NEAR(t, 3.0 - 1.0 / std::sqrt(2.0), 1e-12);
}

TEST(RayIntersection, BoxTopSeenFromAboveAndMissedOverTheTop) {
  const Solid box = Solid::box(5.0, 0.0, 2.0, 2.0, 0.0, 0.0, 1.0, 0);
  int face = -1;
  EXPECT_DOUBLE_EQ(intersectSolid(box, rayFrom(5.0, 0.5, 3.0, 0.0, 0.0, -1.0), kNoHit, &face), 2.0);
  EXPECT_EQ(face, kFaceTop);
  EXPECT_EQ(intersectSolid(box, rayFrom(0.0, 0.0, 1.5, 1.0, 0.0, 0.0), kNoHit, &face), kNoHit);
  // Descending at 1:10 from z = 1.5 the ray is at z = 1.1 over the near face (x = 4) and
  // reaches the top (z = 1) at x = 5.
  EXPECT_NEAR(intersectSolid(box, rayFrom(0.0, 0.0, 1.5, 1.0, 0.0, -0.1), kNoHit, &face), 5.0, 1e-12);
  EXPECT_EQ(face, kFaceTop);
}

TEST(RayIntersection, NoHitFromInsideOrBeyondTheLimit) {
  const Solid box = Solid::box(5.0, 0.0, 2.0, 2.0, 0.0, 0.0, 1.0, 0);
  int face = -1;
  EXPECT_EQ(intersectSolid(box, rayFrom(5.0, 0.0, 0.5, 1.0, 0.0, 0.0), kNoHit, &face), kNoHit);
  EXPECT_EQ(intersectSolid(box, rayFrom(0.0, 0.0, 0.5, 1.0, 0.0, 0.0), 3.9, &face), kNoHit);
  EXPECT_EQ(intersectSolid(box, rayFrom(0.0, 0.0, 0.5, -1.0, 0.0, 0.0), kNoHit, &face), kNoHit);
}

TEST(RayIntersection, CylinderSideAndCap) {
  const Solid pole = Solid::cylinder(3.0, 4.0, 1.0, 0.0, 2.0, 0);
  int face = -1;
  // Straight at the axis from 5 m away: the surface is one radius nearer.
  const Ray ray = rayFrom(0.0, 0.0, 1.0, 0.6, 0.8, 0.0);
  EXPECT_NEAR(intersectSolid(pole, ray, kNoHit, &face), 4.0, 1e-12);
  const SurfacePoint point = surfaceOfSolid(pole, face, ray, 4.0);
  EXPECT_NEAR((point.normal - Eigen::Vector3d(-0.6, -0.8, 0.0)).norm(), 0.0, 1e-12);
  // A ray grazing past at distance 1.5 from the axis misses.
  EXPECT_EQ(intersectSolid(pole, rayFrom(0.0, 5.5, 1.0, 1.0, 0.0, 0.0), kNoHit, &face), kNoHit);
  // Offset by half a radius: enters at x = 3 - sqrt(1 - 0.25).
  EXPECT_NEAR(intersectSolid(pole, rayFrom(0.0, 4.5, 1.0, 1.0, 0.0, 0.0), kNoHit, &face),
              3.0 - std::sqrt(0.75), 1e-12);
  // Above the top: misses the side, hits the cap from above.
  EXPECT_EQ(intersectSolid(pole, rayFrom(0.0, 4.0, 2.5, 1.0, 0.0, 0.0), kNoHit, &face), kNoHit);
  EXPECT_DOUBLE_EQ(intersectSolid(pole, rayFrom(3.2, 4.0, 5.0, 0.0, 0.0, -1.0), kNoHit, &face), 3.0);
  EXPECT_EQ(face, kFaceTop);
}

TEST(RayCaster, WallFaceIsHalfAThicknessBeforeItsCentreLine) {
  const World world = worldFromText(
      "[wall.north]\npoints = -5 2; 5 2\nheight = 2.5\nthickness = 0.1\n");
  RayCaster caster(world);
  const RayHit hit = castOne(caster, rayFrom(1.0, 0.0, 1.0, 0.0, 1.0, 0.0));
  EXPECT_NEAR(hit.t, 1.95, 1e-12);
  EXPECT_NEAR(hit.surface.normal.y(), -1.0, 1e-12);
  // Over the top of the wall there is nothing (no ceiling).
  EXPECT_EQ(castOne(caster, rayFrom(1.0, 0.0, 1.0, 0.0, 1.0, 1.0)).t, kNoHit);
  // Looking down hits the floor.
  EXPECT_NEAR(castOne(caster, rayFrom(1.0, 0.0, 1.0, 0.0, 1.0, -1.0)).t, 1.0, 1e-12);
}

TEST(RayCaster, TableTopIsHitFromTheSideAndFromBelowAndTheRayPassesUnderIt) {
  // Top 1.2 x 0.8 at (2, 0), surface at 0.72, 0.03 thick: underside at 0.69, near edge x = 1.4.
  const World world = worldFromText(
      "[table.t]\ncenter = 2 0\nsize = 1.2 0.8\nheight = 0.72\ntop_thickness = 0.03\n"
      "[wall.back]\npoints = 5 -3; 5 3\n");
  RayCaster caster(world);
  // Level through the slab: the edge.
  RayHit hit = castOne(caster, rayFrom(0.0, 0.0, 0.705, 1.0, 0.0, 0.0));
  EXPECT_NEAR(hit.t, 1.4, 1e-12);
  // Rising 1:10 from 0.5: under the near edge at x = 1.4 (z = 0.64), reaches 0.69 at x = 1.9.
  hit = castOne(caster, rayFrom(0.0, 0.0, 0.5, 1.0, 0.0, 0.1));
  EXPECT_NEAR(hit.t, 1.9, 1e-12);
  EXPECT_NEAR(hit.surface.normal.z(), -1.0, 1e-12);
  // Level at 0.3 between the legs: under the table to the wall's face at 4.95.
  hit = castOne(caster, rayFrom(0.0, 0.0, 0.3, 1.0, 0.0, 0.0));
  EXPECT_NEAR(hit.t, 4.95, 1e-12);
  // Through a leg: legs stand 0.05 + 0.02 in from the corners, at (2 - 0.53, 0.33).
  hit = castOne(caster, rayFrom(0.0, 0.33, 0.3, 1.0, 0.0, 0.0));
  EXPECT_NEAR(hit.t, 2.0 - 0.53 - 0.02, 1e-12);
}

// The nearest hit of `ray` among the floor, the ceiling and every solid, static or moving.
double nearestOfAll(const World& world, const std::vector<Solid>& moving, const Ray& ray) {
  double nearest = ray.origin.z() > 0.0 ? intersectHorizontalPlane(0.0, ray, kNoHit) : kNoHit;
  if (world.ceiling_height > 0.0 && ray.origin.z() < world.ceiling_height) {
    nearest = std::min(nearest, intersectHorizontalPlane(world.ceiling_height, ray, kNoHit));
  }
  for (const auto* solids : {&world.solids, &moving}) {
    for (const auto& solid : *solids) {
      int face = 0;
      nearest = std::min(nearest, intersectSolid(solid, ray, kNoHit, &face));
    }
  }
  return nearest;
}

// RayCaster::rowSurfaces of every row of the last cast, field for field what hit() gives each
// pixel: bit for bit, so that the renderer's images do not change.
void expectRowsAsEachPixelsHit(const RayCaster& caster, const PixelRays& rays, const std::string& view) {
  RowSurfaces row;
  for (int y = 0; y < rays.height; ++y) {
    caster.rowSurfaces(y, row);
    size_t seen = 0;
    for (int x = 0; x < rays.width; ++x) {
      const RayHit hit = caster.hit(x, y);
      ASSERT_EQ(row.t[x], hit.t) << view << " pixel " << x << ", " << y;
      if (hit.t == kNoHit) continue;
      ASSERT_LT(seen, row.count) << view << " row " << y;
      const size_t i = seen++;
      ASSERT_EQ(row.column[i], x) << view << " row " << y;
      const std::string where = view + " pixel " + std::to_string(x) + ", " + std::to_string(y);
      ASSERT_EQ(row.x[i], hit.surface.position.x()) << where;
      ASSERT_EQ(row.y[i], hit.surface.position.y()) << where;
      ASSERT_EQ(row.z[i], hit.surface.position.z()) << where;
      ASSERT_EQ(row.normal_x[i], hit.surface.normal.x()) << where;
      ASSERT_EQ(row.normal_y[i], hit.surface.normal.y()) << where;
      ASSERT_EQ(row.normal_z[i], hit.surface.normal.z()) << where;
      ASSERT_EQ(row.u[i], hit.surface.u) << where;
      ASSERT_EQ(row.v[i], hit.surface.v) << where;
      ASSERT_EQ(row.texture[i], hit.texture) << where;
      ASSERT_EQ(row.texture_offset[i], hit.texture_offset) << where;
    }
    ASSERT_EQ(row.count, seen) << view << " row " << y;
  }
}

// Silhouettes must never lose a pixel: every pixel of random views, from anywhere in the world
// (inside solids, against walls, under tables) looking anywhere, gets the nearest hit of all;
// and the rows give every pixel's hit as hit() does.
void expectEveryPixelHitsTheNearestSolid(const World& world, const std::vector<Solid>& moving, int seed) {
  RayCaster caster(world);
  caster.setMovingSolids(moving);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x_position(world.bounds[0], world.bounds[2]);
  std::uniform_real_distribution<double> y_position(world.bounds[1], world.bounds[3]);
  std::uniform_real_distribution<double> height(0.05, 2.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> pitch(-1.2, 1.2);
  std::uniform_real_distribution<double> focal(10.0, 60.0);
  for (int view = 0; view < 60; ++view) {
    const double yaw = angle(random);
    const double down_angle = pitch(random);
    const double roll = angle(random);
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(down_angle, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    PixelRays rays;
    rays.origin = Eigen::Vector3d(x_position(random), y_position(random), height(random));
    rays.forward = rotation.col(0);
    const double f = focal(random);
    rays.right = rotation.col(1) / f;
    rays.down = rotation.col(2) / f;
    rays.width = 48;
    rays.height = 36;
    rays.cx = 23.5;
    rays.cy = 17.5;
    caster.cast(rays);
    for (int y = 0; y < rays.height; ++y) {
      for (int x = 0; x < rays.width; ++x) {
        ASSERT_EQ(caster.hit(x, y).t, nearestOfAll(world, moving, rays.ray(x, y)))
            << "view " << view << " pixel " << x << ", " << y;
      }
    }
    expectRowsAsEachPixelsHit(caster, rays, "view " + std::to_string(view));
  }
}

TEST(RayCaster, SilhouettesFindTheSameHitsAsTestingEverySolidInTheOffice) {
  const World world = loadWorld(worldsDirectory() + "/office.ini");
  expectEveryPixelHitsTheNearestSolid(world, MovingTraffic(world).solids(), 7);
}

TEST(RayCaster, SilhouettesFindTheSameHitsAsTestingEverySolidInGeneratedWorlds) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    const World world = worldFromText(generateWorld(seed).ini_text);
    expectEveryPixelHitsTheNearestSolid(world, MovingTraffic(world).solids(), static_cast<int>(seed));
  }
}

}  // namespace
}  // namespace stereonav
