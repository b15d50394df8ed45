#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/TMetricMapTypesRegistry.h>

#include <memory>
#include <vector>

#include "occupancy_grid/disparity_scan_inserter.h"
#include "occupancy_grid/disparity_scan_source.h"
#include "occupancy_grid/disparity_tagged_grid.h"
#include "occupancy_grid/grid_options.h"
#include "sensor_model/sensor_model_options.h"

namespace stereonav {

struct StereoGridMapOptions {
  GridLimits limits;
  GridUpdateOptions update;
  SensorModelOptions sensor_model;
};

// The paper's stereo occupancy grid (sections 3-4) as an MRPT metric map: it sits in a
// CMultiMetricMap next to MRPT's own maps and takes observations through insertObservation().
// It takes CObservationDisparityScan natively, and any other observation a registered
// DisparityScanSource can turn into one; everything else is refused (returns false), so a
// sensory frame holding a disparity scan and its virtual laser scan updates each map with what
// it understands.
//
// In a CMultiMetricMap ini definition (mrpt::maps::TSetOfMetricMapInitializers):
//   [map]
//   stereoOccupancyGrid_count = 1
//   [map_stereoOccupancyGrid_00_creationOpts]   ; GridLimits keys (+ MRPT's generic map keys)
//   resolution = 0.05
//   [map_stereoOccupancyGrid_00_insertOpts]     ; GridUpdateOptions + SensorModelOptions keys
//   update_step = 20
// The _insertOpts section rejects unknown keys; _creationOpts is shared with MRPT's generic
// keys (enableSaveAs3DObject, ...) and is read leniently, as MRPT does.
class CStereoOccupancyGridMap : public mrpt::maps::CMetricMap {
  DEFINE_SERIALIZABLE(CStereoOccupancyGridMap, stereonav)

 public:
  explicit CStereoOccupancyGridMap(const StereoGridMapOptions& options = {});

  const StereoGridMapOptions& options() const { return options_; }
  const DisparityTaggedGrid& grid() const { return grid_; }

  // See DisparityScanSource; sources are tried in the order added. Not serialised.
  void addDisparityScanSource(std::shared_ptr<const DisparityScanSource> source);

  bool isEmpty() const override { return is_empty_; }
  // Writes <prefix>.png and the ROS map_server pair <prefix>.yaml + <prefix>.pgm.
  void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
  std::string asString() const override;
  void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;

  MAP_DEFINITION_START(CStereoOccupancyGridMap)
  StereoGridMapOptions options;
  MAP_DEFINITION_END(CStereoOccupancyGridMap)

 private:
  void internal_clear() override;
  bool internal_insertObservation(
      const mrpt::obs::CObservation& observation,
      const std::optional<const mrpt::poses::CPose3D>& robot_pose) override;
  // The paper maps with known poses; this map offers no observation likelihood.
  double internal_computeObservationLikelihood(const mrpt::obs::CObservation& observation,
                                               const mrpt::poses::CPose3D& taken_from) const override;
  bool internal_canComputeObservationLikelihood(
      const mrpt::obs::CObservation& observation) const override;

  StereoGridMapOptions options_;
  DisparityTaggedGrid grid_;
  DisparityScanInserter inserter_;
  std::vector<std::shared_ptr<const DisparityScanSource>> sources_;
  bool is_empty_ = true;
};

}  // namespace stereonav
