#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "simulator/world.h"

namespace stereonav {

// World files are MRPT ini files (mrpt::config::CConfigFile). Every object is one section named
// <kind>.<name>; keys not listed here are rejected with the nearest known key, and every error
// names the file, the section and the key. Coordinates are metres in the world frame (x, y on the
// floor, z up, floor at z = 0); angles are degrees; lists are space separated; point lists are
// "x y; x y; ...". Comments take a whole line starting with '#' or ';', or follow a value
// after '//' (a ';' after a value would be read as part of the value).
//
// [world]            (optional)
//   bounds = x_min y_min x_max y_max   region of the ground-truth map (default: around all objects)
//   start_pose = x y yaw_deg           where a robot starts (default 0 0 0)
//   wall_thickness = 0.1               default thickness of walls
//   floor_texture = true               false: the floor is flat paint (no texture to match)
//   floor = <texture>                  texture of a textured floor (default: default)
//   ceiling_height = 0                 > 0 adds a ceiling; 0: looking up sees nothing (infinity)
//   ceiling = <texture>
//   lighting_change = 0                brightness gain 1 + a sin(2 pi t / lighting_period_s)
//   lighting_period_s = 4
// [texture.<name>]   a surface pattern, anchored to the surface it is on (surface_texture.h)
//   type = noise       value noise summed over octaves (rich texture, easy to match)
//        | paint       flat albedo (no texture: the matcher's texture test rejects it)
//        | stripes     square wave (repetitive texture: ghost matches, paper section 4.1)
//        | poster      noise inside a rectangle, flat paint around it
//   mean = 0.5  contrast = 0.3 (albedo 0..1)   scales_m = 0.4 0.1 0.025 (noise octave wavelengths)
//   period_m = 0.1  duty = 0.5  orientation = vertical | horizontal (stripes)
//   rect = u0 v0 u1 v1  (poster frame in surface metres: on a side face u runs from the middle
//                        of the face to the right as seen from the front, v is the height)
//   seed = 1
//   Texture detail finer than about two pixels fades to the mean (anti-aliasing).
//   "default" exists unless redefined: multi-scale noise 0.4 0.1 0.025 m, mean 0.5, contrast 0.3.
// [wall.<name>]      a polyline of upright slabs
//   points = x y; x y; ...   height = 2.5   thickness = <wall_thickness>   texture = default
// [box.<name>]       center = x y   size = sx sy   yaw_deg = 0   z = 0 (bottom)   height = 1
//                    texture = default
// [cylinder.<name>]  center = x y   radius = 0.1   z = 0   height = 1   texture = default
// [table.<name>]     a top slab on four legs: the paper's most dangerous obstacle (section 6.1)
//   center = x y   size = sx sy   yaw_deg = 0   height = 0.72 (top surface)   top_thickness = 0.03
//   leg_radius = 0.02   leg_inset = 0.05   texture = default   leg_texture = <texture>
// [picket_fence.<name>]  identical upright pickets from one point to another (section 4.1)
//   from = x y   to = x y   picket_width = 0.05   gap = 0.07   height = 1   thickness = 0.02
//   rail_heights = <heights of horizontal rails' centres, may be empty>   rail_size = 0.05
//   texture = default
// [moving.<name>]    a box or a person-sized cylinder going round its waypoints (from the last
//                    back to the first) at constant speed; not part of the ground-truth map
//   shape = cylinder | box   radius = 0.25 (cylinder)   size = sx sy (box)   yaw_deg = 0 (box)
//   height = 1.7   path = x y; x y; ...   speed = 0.5 (m/s)   texture = default
// [floor_plan.<name>]  a ROS map_server floor plan (YAML + image): occupied cells become walls
//   map = plan.yaml (relative to the world file)   height = 2.5   texture = default
//   flat_share = 0 (share of the walls given flat_texture)   flat_texture = <texture>   seed = 1
World loadWorld(const std::string& path);

// The same from an already opened configuration; `file_name` is only used in error messages.
World loadWorld(const mrpt::config::CConfigFileBase& config, const std::string& file_name);

}  // namespace stereonav
