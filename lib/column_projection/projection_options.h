#pragma once

#include "common/ini_section.h"

namespace stereonav {

// The robot's body volume (paper section 3.3): points higher than floor_clearance_m above the
// floor and no higher than robot_height_m are obstacles; the floor itself (texture the matcher
// happily finds) and whatever the robot passes under are not.
struct ProjectionOptions {
  double floor_clearance_m = 0.05;
  double robot_height_m = 1.0;
  // A column's reading: 0 = its largest disparity inside the body volume (the paper). > 0 = the
  // median of its disparities within this many pixels of the largest: the pixels of the nearest
  // surface, of which the largest is the noise extreme (the maximum of tens of noisy pixels
  // reads the surface too close).
  double surface_band_px = 0.0;
  // With surface_band_px: true = only the virtual laser scan (what a scan matcher, a ROS topic and
  // a recorded rawlog read) reads each column's surface (DisparityScan::column_surface); the
  // reading that the map and a guard take stays the largest, the surface's nearest point, which a
  // robot must keep clear of: the median places a wall where it is, but a table's top or a box's
  // side receding from its edge within the band, behind that edge. Only where nothing matches
  // the scans against that map (the walls' lines do not care where the map put them).
  bool surface_band_scan_only = false;
  // A column whose reading is deeper than this (depth Z along the optical axis, metres) has no
  // reading: its region of uncertainty grows as Z^2 (paper section 3.2, equation 1), and one
  // far, deep region marks cells behind the obstacle that no later, closer view can clear. The
  // limit applies to the reading, not pixel by pixel: of a surface just beyond it only the
  // pixels that noise brings nearer would pass. 0 = no limit.
  double max_depth_m = 0.0;
  // A surface with no texture (flat paint) matches nothing, so the body volume holds none of its
  // pixels; but the textured floor in front of it, matched from the image's bottom up, ends at its
  // foot. A column whose floor ends nearer than this depth (Z along the optical axis, metres),
  // below pixels that mostly match nothing up to floor_clearance_m at that depth, reads an
  // obstacle standing at the floor's end, unless it sees one nearer. Near only: far away the
  // floor's texture fades below what the matcher finds, and its end is no foot. 0 = off (the
  // paper's projection).
  double floor_end_max_depth_m = 0.0;
  // The same foot, nearer than this depth, in a column with a reading beyond it or with none
  // (DisparityScan::column_clear_end): a reading is kept, but its CLEAR stops at the foot, and the
  // explorer's guard stops short of the foot (unmatched_foot_points.h). A window-based matcher
  // gives the pixels of a flat-painted wall next to a textured surface far behind it that
  // surface's disparity (the window holds only its texture), so the column reads far and its
  // CLEAR runs through the wall; its floor, though, ends at the wall. 0 = off.
  double floor_end_clear_max_depth_m = 0.0;
  // Below the nearest floor the camera can see, it sees nothing; a surface the matcher cannot
  // match (flat paint, or one nearer than the largest disparity searched) standing there fills
  // the image's bottom rows and leaves no trace in the scan. So a column whose rows that would
  // show the floor, from its nearest visible point to this much deeper (depth Z, metres), mostly
  // match nothing is blind (DisparityScan::column_blind): it cannot tell that the ground right
  // ahead is clear. The robot must not drive where it cannot see (issue 18); the scan's reading
  // is left as it is, as nothing tells how near the surface is. 0 = off.
  double near_floor_m = 0.0;
  // The virtual laser scan's maxRange: obstacles farther than this are left out of it.
  double scan_max_range_m = 10.0;
};

// Section [projection]. Keys: floor_clearance_m, robot_height_m, surface_band_px,
// surface_band_scan_only, max_depth_m, floor_end_max_depth_m, floor_end_clear_max_depth_m, near_floor_m, scan_max_range_m.
// Throws ConfigError on bad values.
ProjectionOptions loadProjectionOptions(IniSection& section);

}  // namespace stereonav
