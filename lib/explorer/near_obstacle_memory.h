#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace stereonav {

struct NearObstacleMemoryOptions {
  // Obstacle points the stereo head sees closer than this to the robot are remembered.
  double remember_within_m = 2.0;
  // A remembered point is forgotten when a later scan sees past it, judged only from this far
  // out: nearer, below the tilted cameras' view, a low obstacle drops out of sight and the scan
  // sees the wall behind it.
  double judge_beyond_m = 1.0;
  // "Seeing past": the scan has at least two points in the bearing bins (bearing_window_rad wide)
  // of the remembered point and its two neighbours, all more than `see_through_margin_m` beyond it.
  double see_through_margin_m = 0.3;
  double bearing_window_rad = 0.035;  // 2 degrees: the camera sits ahead of the robot's centre
  double cell_m = 0.05;               // points are kept one per cell of this size
  // A point is remembered once scans from two robot positions this far apart have shown it where
  // the map confirms an obstacle: standing still, the same floor seen a little too near piles up
  // OCC evidence in the same cells.
  double distinct_views_m = 0.3;
};

// What the stereo head has seen up close, kept until it is seen to be gone. The paper's linear
// grid update forgets an obstacle as soon as far views see past it (section 3.4), which is right
// for the person who walked on, but wrong for a chair seat or table top that stereo sees only
// from up close and that far views see under (section 6.1): in the office runs the robot drove
// into chairs the map had lost. Up close the cameras do see such things, so the explorer keeps
// them until a later view from nearby sees past them: a moving obstacle that has left is
// forgotten, a chair is not. Only points the map confirms, seen from two places, are kept (the
// update rule wants repeated OCC evidence), so that noisy readings (the floor seen a few
// centimetres high) are not obstacles for ever.
class NearObstacleMemory {
 public:
  explicit NearObstacleMemory(const NearObstacleMemoryOptions& options) : options_(options) {}

  // `sensed`: the newest scan's obstacle points in the robot frame, taken at `pose` (map frame);
  // `confirmed(x, y)`: whether the map holds an obstacle at map point (x, y).
  void update(const std::vector<mrpt::math::TPoint2D>& sensed, const mrpt::poses::CPose2D& pose,
              const std::function<bool(double x, double y)>& confirmed);

  // Remembers map points without the map's confirmation: what physically stopped the robot.
  void remember(const std::vector<mrpt::math::TPoint2D>& points);

  // Forgets every point where `confirmed(x, y)` is false; returns how many.
  size_t forgetUnconfirmed(const std::function<bool(double x, double y)>& confirmed);

  // The remembered points, map frame, in no particular order.
  const std::vector<mrpt::math::TPoint2D>& points() const { return points_; }
  // The remembered points within `radius` of map point (x, y), and some a little farther; in the
  // order of their cells (by column, then row).
  std::vector<mrpt::math::TPoint2D> pointsNear(double x, double y, double radius) const;
  size_t size() const;

 private:
  struct Candidate {
    mrpt::math::TPoint2D point;       // the newest sighting
    mrpt::math::TPoint2D first_view;  // where the robot stood when it first saw it
  };
  using Key = std::pair<long, long>;
  Key keyOf(double x, double y) const;
  // Remembers `point` in the cell `key`, replacing the point it held.
  void rememberCell(const Key& key, const mrpt::math::TPoint2D& point);
  // Forgets the remembered cell at `it`; returns the iterator after it.
  std::map<Key, size_t>::iterator forget(std::map<Key, size_t>::iterator it);

  NearObstacleMemoryOptions options_;
  // The remembered cells: their points side by side, each key's at its slot (the last point
  // fills the slot a forgotten one leaves). Every map reads all the points, and walking a tree of
  // some ten thousand cells for them took 3% of an exploration run. Apart from the candidates,
  // which pile up along every wall the robot passes.
  std::map<Key, size_t> remembered_;
  std::vector<mrpt::math::TPoint2D> points_;
  std::vector<Key> keys_;  // per slot
  std::map<Key, Candidate> candidates_;  // seen from one place so far
};

}  // namespace stereonav
