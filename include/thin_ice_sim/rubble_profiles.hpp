// The rubble pile's side and top profiles (paper Section 5.1.2, Figs. 13 and 15): what a camera
// beside and above the basin sees of the ice above the waterline.
#pragma once

#include <vector>

#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

struct RubbleProfiles {
  double bin = 0.0;                 ///< [m] bin width along x (side) and y (top)
  std::vector<double> side_x;       ///< [m] bin centres along x
  std::vector<double> side_height;  ///< [m] highest cell top (z + h/2) in the bin; 0 where none is above water
  std::vector<double> top_y;        ///< [m] bin centres along y
  std::vector<double> top_extent;   ///< [m] distance from the structure's toe to the farthest cell
                                    ///< above water (top > 0) in the bin, 0 where none
};

/// Profiles of the cells `cells` (from Simulation::cells()) for the structure in `params`:
/// side bins span from `reach` metres in front of the toe to the top of the face.
RubbleProfiles computeRubbleProfiles(const std::vector<CellSnapshot>& cells, const Params& params,
                                     double bin, double reach);

}  // namespace thin_ice
