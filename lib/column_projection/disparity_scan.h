#pragma once

#include <vector>

#include "disparity/disparity_image.h"

namespace stereonav {

// The paper's "stereo scan" (section 3.3, figure 5c): for each column of the reference image,
// the largest valid disparity among the pixels whose 3D point lies inside the robot's body
// volume, i.e. the closest obstacle seen through that column; kInvalidDisparity where the column
// saw none.
struct DisparityScan {
  std::vector<float> column_disparity;

  int columns() const { return static_cast<int>(column_disparity.size()); }
  bool valid(int column) const { return isValidDisparity(column_disparity[column]); }
};

}  // namespace stereonav
