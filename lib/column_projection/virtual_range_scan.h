#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// Turns a disparity scan into a virtual 2D laser scan, so stock MRPT maps (COccupancyGridMap2D,
// CSimplePointsMap) and icp-slam can use the stereo head like a laser.
//
//  - sensorPose: the reference camera's optical centre dropped onto the floor plane (z = 0),
//    turned by the heading of its optical axis; no pitch or roll, so MRPT treats it as horizontal.
//  - Rays: one per image column, evenly spaced in angle over the camera's horizontal field of
//    view (aperture = twice the widest bearing of an image corner), counter-clockwise
//    (rightToLeft = true): ray 0 is the rightmost, at -aperture/2, as getScanAngle() computes.
//  - Each column's obstacle (its 3D point from column_row and column_disparity) covers the
//    bearings between its pixel's left and right edges; every ray in that span gets the horizontal
//    distance from the sensor to the obstacle (the nearest one if spans overlap). Columns are not
//    evenly spaced in angle and a tilted camera's bearings change with the row, which this handles
//    exactly; a ray is off its obstacle's bearing by at most half a pixel.
//  - Rays that meet no obstacle, or only obstacles beyond max_range_m, are invalid (range =
//    maxRange).
// When inserting into a COccupancyGridMap2D, set insertionOptions.considerInvalidRangesAsFreeSpace
// = false: an invalid ray means the matcher found nothing, not that nothing is there.
// The caller sets the timestamp and sensorLabel. Requires scan.column_row (ColumnProjector output)
// and the rig's image width; throws std::invalid_argument otherwise.
mrpt::obs::CObservation2DRangeScan makeVirtualRangeScan(const DisparityScan& scan,
                                                         const CameraRig& rig,
                                                         double max_range_m);

}  // namespace stereonav
