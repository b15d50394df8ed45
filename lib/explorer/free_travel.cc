#include "explorer/free_travel.h"

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

// Below this turn rate per unit speed (1/m) the arc is a straight line for our purposes: over
// the few metres the guard looks ahead it deviates by less than a millimetre.
constexpr double kStraightCurvature = 1e-4;

// How far the disc of radius `radius_m` travels before touching the point (px, py), in the
// mirrored frame where the robot moves forwards and turns left on a circle of `turn_radius`
// (0: straight); `horizon_m` when it never does. A point already under the disc gives 0 if it
// lies ahead and horizon_m if it lies behind (moving away from it).
double travelTo(double px, double py, double radius_m, double turn_radius, double horizon_m) {
  const double r2 = radius_m * radius_m;
  if (px * px + py * py < r2) return px > 0.0 ? 0.0 : horizon_m;
  if (turn_radius == 0.0) {
    return std::abs(py) < radius_m && px > 0.0 ? px - std::sqrt(r2 - py * py) : horizon_m;
  }
  // The centre runs round the instantaneous centre of rotation (0, R) at angle phi:
  // c(phi) = (R sin phi, R (1 - cos phi)); seen from the centre of rotation it lies at
  // polar angle phi - pi/2. Contact while |c - p| < r, i.e. while
  // cos(phi - pi/2 - beta) > (R^2 + rho^2 - r^2) / (2 R rho), beta and rho the polar
  // angle and distance of p from the centre of rotation.
  const double qx = px, qy = py - turn_radius;
  const double rho = std::hypot(qx, qy);
  const double k = (turn_radius * turn_radius + rho * rho - r2) / (2.0 * turn_radius * rho);
  if (k >= 1.0) return horizon_m;  // the swept annulus misses the point
  const double half_width = std::acos(std::max(-1.0, k));
  const double first = std::atan2(qy, qx) + M_PI / 2.0 - half_width;
  const double angle = std::fmod(std::fmod(first, 2.0 * M_PI) + 2.0 * M_PI, 2.0 * M_PI);
  return turn_radius * angle;
}

}  // namespace

FreeTravel freeTravel(const std::vector<mrpt::math::TPoint2D>& obstacles, double radius_m, double margin_m,
                      double speed_mps, double turn_rate, double horizon_m) {
  if (speed_mps == 0.0) return {horizon_m, horizon_m, horizon_m};
  // Mirror the frame so that the robot moves forwards (x) and turns left (y): the sweep is symmetric.
  const double x_sign = speed_mps > 0.0 ? 1.0 : -1.0;
  const double curvature = turn_rate / speed_mps;  // signed: left turn while moving forwards > 0
  const double y_sign = curvature * x_sign >= 0.0 ? 1.0 : -1.0;
  const double turn_radius = std::abs(curvature) < kStraightCurvature ? 0.0 : 1.0 / std::abs(curvature);
  const double wide = radius_m + margin_m;
  FreeTravel free{horizon_m, horizon_m, horizon_m};
  for (const mrpt::math::TPoint2D& obstacle : obstacles) {
    const double px = x_sign * obstacle.x;
    const double py = y_sign * obstacle.y;
    const double bare = travelTo(px, py, radius_m, turn_radius, horizon_m);
    free.body_contact_m = std::min(free.body_contact_m, bare);
    if (px * px + py * py < wide * wide) {
      free.to_contact_m = std::min(free.to_contact_m, bare);
      // Still ahead: the robot keeps creeping until it has passed it. The bare disc's sweep alone
      // let it speed up here, into the unseen rest of what the point belongs to (a table's edge
      // beside the body, out of the cameras' view).
      if (px > 0.0) free.beside_m = 0.0;
      continue;
    }
    double& kind = bare < horizon_m ? free.to_contact_m : free.beside_m;
    kind = std::min(kind, travelTo(px, py, wide, turn_radius, horizon_m));
  }
  free.to_contact_m = std::max(0.0, free.to_contact_m);
  free.beside_m = std::max(0.0, free.beside_m);
  free.body_contact_m = std::max(0.0, free.body_contact_m);
  return free;
}

}  // namespace stereonav
