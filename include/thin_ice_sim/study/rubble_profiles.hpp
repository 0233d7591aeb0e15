// The rubble pile's side and top profiles (paper Section 5.1.2, Figs. 13 and 15): what a camera
// beside and above the basin sees of the pile above the waterline.
#pragma once

#include <string>
#include <vector>

#include "thin_ice_sim/params.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

/// How the profiles are binned and what counts as pile.
struct RubbleProfileSpec {
  double bin = 0.1;    ///< [m] bin width along x (side) and y (top)
  double reach = 4.0;  ///< [m] the side profile starts this far in front of the toe
  /// [-] a cell is pile when its centroid is more than this many thicknesses above its floating
  /// height: level ice floats with its top a few millimetres above the waterline (freeboard
  /// h - draft), and without this the top profile would count the whole floating sheet.
  double min_lift_thicknesses = 0.5;
};

struct RubbleProfiles {
  double bin = 0.0;                 ///< [m]
  std::vector<double> side_x;       ///< [m] bin centres along x
  std::vector<double> side_height;  ///< [m] highest pile-cell top (z + h/2) in the bin; 0 where none
  std::vector<double> top_y;        ///< [m] bin centres along y
  std::vector<double> top_extent;   ///< [m] distance from the structure's toe to the farthest pile
                                    ///< cell (by centroid) in the bin, 0 where none
};

/// Profiles of `cells` (from Simulation::cells() or a snapshot) for the structure and ice in
/// `params`: only pile cells (RubbleProfileSpec) whose top is above the waterline are seen; side
/// bins span from `reach` in front of the toe to the top of the face, top bins the structure width.
RubbleProfiles computeRubbleProfiles(const std::vector<CellSnapshot>& cells, const Params& params,
                                     const RubbleProfileSpec& spec = RubbleProfileSpec{});

/// The profiles as CSV: "profile,coordinate_m,value_m", one line per bin, side then top.
std::string rubbleProfilesCsv(const RubbleProfiles& profiles);

}  // namespace thin_ice
