#pragma once

#include <cstdint>

#include "common/ini_section.h"

namespace stereonav {

// Where the grid starts and how it grows. Keys named as in MRPT's COccupancyGridMap2D.
struct GridLimits {
  double min_x = -10.0;
  double max_x = 10.0;
  double min_y = -10.0;
  double max_y = 10.0;
  double resolution = 0.05;  // metres per cell
  // When a scan's regions leave the grid it grows by whole cells to cover them plus this margin,
  // so that a moving robot does not regrow the grid on every scan.
  double growth_margin_m = 2.0;
  // Bound on the grid's cells (about 6 bytes each): it stops growing there, and readings beyond
  // are left out. 16M cells are 200 m x 200 m at 5 cm.
  int64_t max_cells = 16'000'000;
};

// Bound on |min_x|, |max_x|, |min_y|, |max_y|, metres.
constexpr double kMaxGridCoordinate = 1e6;

// Keys: min_x, max_x, min_y, max_y, resolution, growth_margin_m, max_cells.
GridLimits loadGridLimits(IniSection& section);

enum class CellClass { kFree, kUnknown, kOccupied };

// The occupancy value G of a cell (paper section 3.4): 0..255 clipped to [g_min, g_max], with
// "unknown" at the midpoint. The paper writes the midpoint (Gmax - Gmin) / 2 (with Gmin = 0);
// we take g_min + (g_max - g_min) / 2 rounded up, i.e. 128 for 0..255, so that one OCC and one
// CLEAR update of K around it are symmetric about 127.5.
// G maps to an occupancy probability p = G / 255 everywhere we convert (MRPT grid, ROS map), so
// the free/occupied thresholds below carry over as free_below / 255 and occupied_above / 255.
struct OccupancyScale {
  int g_min = 0;
  int g_max = 255;
  int free_below = 50;       // G < free_below: free (paper: conservative for planning)
  int occupied_above = 150;  // G > occupied_above: definitely obstructed

  uint8_t unknown() const { return static_cast<uint8_t>(g_min + (g_max - g_min + 1) / 2); }
  CellClass classify(uint8_t g) const {
    if (g < free_below) return CellClass::kFree;
    if (g > occupied_above) return CellClass::kOccupied;
    return CellClass::kUnknown;
  }
  static double occupiedProbability(uint8_t g) { return g / 255.0; }
};

// The linear update rule (paper section 3.4) and accuracy preservation (section 4.3).
struct GridUpdateOptions {
  OccupancyScale scale;
  int update_step = 20;  // K: added over OCC, subtracted over CLEAR
  // Skip a reading's OCC update when its region already holds obstacle evidence from a higher
  // disparity (a closer, more precise reading); see DisparityScanInserter.
  bool accuracy_preservation = true;
  // > 0: cells cleared from within this range (metres) of the camera are spared by OCC updates
  // of readings from farther (depth f B / d beyond it); see DisparityScanInserter. 0 = off, the
  // paper's rule alone.
  double free_preservation_range_m = 0.0;
};

// Keys: update_step, g_min, g_max, free_below, occupied_above, accuracy_preservation,
// free_preservation_range_m.
GridUpdateOptions loadGridUpdateOptions(IniSection& section);

}  // namespace stereonav
