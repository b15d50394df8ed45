#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace stereonav {

// How straight stretches of wall are picked out of a scan (WallHeadingOptions holds these).
struct WallSegmentOptions {
  // Only readings nearer than this: a stereo reading's range error grows with its range squared
  // (paper section 3.2), and a far wall's readings scatter too much to give a direction.
  double max_range_m = 2.5;
  // Neighbouring readings farther apart than this belong to different surfaces.
  double max_gap_m = 0.2;
  // A run of readings is split at its reading farthest from the chord while that one is farther
  // than this (split-and-merge line extraction).
  double split_tolerance_m = 0.05;
  // A segment gives a direction only with this many readings over this length.
  int min_points = 12;
  double min_length_m = 0.6;
  // Neighbouring readings share their errors over this many readings (a stereo scan's columns
  // share the SAD window: loadMappingOptions sets the [stereo] window), so a segment of n
  // readings tells its direction and offset as n / correlated_readings independent ones would.
  int correlated_readings = 1;
};

// A straight stretch of wall in a scan, in the robot frame.
struct WallSegment {
  double direction_rad = 0.0;  // of the fitted line, in [-pi/2, pi/2): a line has no sense
  double sigma_rad = 0.0;      // one sigma of direction_rad, from the fit's residuals
  double length_m = 0.0;
  // The direction from the robot toward the line, square to it (in [-pi, pi)): the side of the
  // wall the robot sees.
  double normal_rad = 0.0;
  // The readings' centroid, and one sigma of where it lies across the line: with the wall's
  // direction known from elsewhere, the centroid alone says how far the wall is (a fitted line's
  // tilt, carried to the foot of its normal through the robot, would not).
  mrpt::math::TPoint2D centroid;
  double centroid_sigma_m = 0.0;
  // The stretch's ends, its first and last readings put onto the line.
  mrpt::math::TPoint2D first;
  mrpt::math::TPoint2D last;
};

// Straight segments of the scan's valid readings, in ray order: runs broken where neighbours are
// more than max_gap_m apart, split recursively at the reading farthest from the run's chord,
// then each fitted by total least squares. Segments shorter than min_length_m or with fewer than
// min_points readings are left out.
std::vector<WallSegment> wallSegments(const mrpt::obs::CObservation2DRangeScan& scan,
                                      const WallSegmentOptions& options);

}  // namespace stereonav
