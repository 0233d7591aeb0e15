#include "thin_ice_sim/study/rubble_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "thin_ice_sim/physics/water.hpp"

namespace thin_ice {

RubbleProfiles computeRubbleProfiles(const std::vector<CellSnapshot>& cells, const Params& params,
                                     const RubbleProfileSpec& spec) {
  RubbleProfiles r;
  r.bin = spec.bin;
  const StructureParams& s = params.structure;
  const double h = params.ice.thickness;
  const double pile_z = floatingCentroidHeight(h, params.ice.density, params.water.density) + spec.min_lift_thicknesses * h;
  const double x0 = s.toe_x - spec.reach;
  const double x1 = structureFaceX(s, s.height);
  const int nx = std::max(1, static_cast<int>(std::ceil((x1 - x0) / spec.bin)));
  const double y0 = -0.5 * s.width;
  const int ny = std::max(1, static_cast<int>(std::ceil(s.width / spec.bin)));
  r.side_x.resize(nx);
  r.side_height.assign(nx, 0.0);
  r.top_y.resize(ny);
  r.top_extent.assign(ny, 0.0);
  for (int k = 0; k < nx; ++k) r.side_x[k] = x0 + (k + 0.5) * spec.bin;
  for (int k = 0; k < ny; ++k) r.top_y[k] = y0 + (k + 0.5) * spec.bin;
  for (const CellSnapshot& c : cells) {
    const double top = c.z + 0.5 * h;
    if (!(c.z > pile_z) || !(top > 0.0)) continue;  // level ice, or pile under water: not seen
    const int ix = static_cast<int>(std::floor((c.x - x0) / spec.bin));
    if (ix >= 0 && ix < nx) r.side_height[ix] = std::max(r.side_height[ix], top);
    const int iy = static_cast<int>(std::floor((c.y - y0) / spec.bin));
    if (iy >= 0 && iy < ny && c.x > x0 && c.x < x1) r.top_extent[iy] = std::max(r.top_extent[iy], s.toe_x - c.x);
  }
  return r;
}

std::string rubbleProfilesCsv(const RubbleProfiles& p) {
  std::ostringstream out;
  out << "profile,coordinate_m,value_m\n";
  for (std::size_t k = 0; k < p.side_x.size(); ++k) out << "side," << p.side_x[k] << "," << p.side_height[k] << "\n";
  for (std::size_t k = 0; k < p.top_y.size(); ++k) out << "top," << p.top_y[k] << "," << p.top_extent[k] << "\n";
  return out.str();
}

}  // namespace thin_ice
