#include "occupancy_grid/observation_disparity_scan.h"

#include <mrpt/serialization/CArchive.h>

#include <ostream>

IMPLEMENTS_SERIALIZABLE(CObservationDisparityScan, CObservation, stereonav)

namespace stereonav {

// Version 1 adds the principal point's row cy, which places a tilted head's readings by their row;
// version 2 the floor ends that stop CLEAR (DisparityScan::column_clear_end); version 3 the
// matcher's range top (DisparityScan::range_top).
uint8_t CObservationDisparityScan::serializeGetVersion() const { return 3; }

void CObservationDisparityScan::serializeTo(mrpt::serialization::CArchive& out) const {
  out << timestamp << sensorLabel;
  out << camera.focal_px << camera.cx << camera.cy << camera.baseline_m << camera.pose_on_robot;
  out.WriteAs<uint32_t>(scan.column_disparity.size());
  out.WriteBufferFixEndianness(scan.column_disparity.data(), scan.column_disparity.size());
  out.WriteAs<uint32_t>(scan.column_row.size());
  for (const int row : scan.column_row) out.WriteAs<int32_t>(row);
  out.WriteAs<uint32_t>(scan.column_clear_end.size());
  out.WriteBufferFixEndianness(scan.column_clear_end.data(), scan.column_clear_end.size());
  for (const int row : scan.column_clear_end_row) out.WriteAs<int32_t>(row);
  out << scan.range_top;
}

void CObservationDisparityScan::serializeFrom(mrpt::serialization::CArchive& in,
                                              uint8_t version) {
  switch (version) {
    case 0:
    case 1:
    case 2:
    case 3: {
      in >> timestamp >> sensorLabel;
      in >> camera.focal_px >> camera.cx;
      if (version >= 1) in >> camera.cy;
      in >> camera.baseline_m >> camera.pose_on_robot;
      scan.column_disparity.resize(in.ReadAs<uint32_t>());
      in.ReadBufferFixEndianness(scan.column_disparity.data(), scan.column_disparity.size());
      scan.column_row.resize(in.ReadAs<uint32_t>());
      for (int& row : scan.column_row) row = in.ReadAs<int32_t>();
      // Without cy the rows cannot be placed: the readings count as seen in the optical axis' row.
      if (version == 0) scan.column_row.clear();
      scan.column_clear_end.clear();
      scan.column_clear_end_row.clear();
      if (version >= 2) {
        scan.column_clear_end.resize(in.ReadAs<uint32_t>());
        in.ReadBufferFixEndianness(scan.column_clear_end.data(), scan.column_clear_end.size());
        scan.column_clear_end_row.resize(scan.column_clear_end.size());
        for (int& row : scan.column_clear_end_row) row = in.ReadAs<int32_t>();
      }
      scan.range_top = kInvalidDisparity;
      if (version >= 3) in >> scan.range_top;
      break;
    }
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationDisparityScan::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  int valid = 0;
  for (int column = 0; column < scan.columns(); ++column) valid += scan.valid(column) ? 1 : 0;
  o << "Disparity scan: " << scan.columns() << " columns, " << valid << " with a disparity\n"
    << "focal_px=" << camera.focal_px << " cx=" << camera.cx << " cy=" << camera.cy
    << " baseline_m=" << camera.baseline_m << "\n"
    << "Camera optical frame on the robot: " << camera.pose_on_robot << "\n";
}

}  // namespace stereonav
