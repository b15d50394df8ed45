#pragma once

#include "simulator/world.h"

namespace stereonav {

// Whether the solid reaches into the height band (z_low, z_high): only those parts of the world
// can touch a robot whose body sweeps that band (paper section 3.3).
bool solidInHeightBand(const Solid& solid, double z_low, double z_high);

// Whether the solid's footprint and a disc of `radius` about (x, y) overlap (touching is not
// overlapping).
bool solidOverlapsDisc(const Solid& solid, double x, double y, double radius);

// Whether the solid's footprint overlaps the interior of the axis-aligned square cell
// [x_min, x_min + size] x [y_min, y_min + size] (touching its border is not overlapping).
bool solidOverlapsCell(const Solid& solid, double x_min, double y_min, double size);

}  // namespace stereonav
