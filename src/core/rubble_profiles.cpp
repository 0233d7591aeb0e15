#include "thin_ice_sim/rubble_profiles.hpp"

#include <algorithm>
#include <cmath>

namespace thin_ice {

RubbleProfiles computeRubbleProfiles(const std::vector<CellSnapshot>& cells, const Params& params,
                                     double bin, double reach) {
  RubbleProfiles r;
  r.bin = bin;
  const StructureParams& s = params.structure;
  const double half_h = 0.5 * params.ice.thickness;
  const double x0 = s.toe_x - reach;
  const double x1 = s.toe_x + s.height / std::tan(s.angle_deg * 3.14159265358979323846 / 180.0);
  const int nx = std::max(1, static_cast<int>(std::ceil((x1 - x0) / bin)));
  const double y0 = -0.5 * s.width;
  const int ny = std::max(1, static_cast<int>(std::ceil(s.width / bin)));
  r.side_x.resize(nx);
  r.side_height.assign(nx, 0.0);
  r.top_y.resize(ny);
  r.top_extent.assign(ny, 0.0);
  for (int k = 0; k < nx; ++k) r.side_x[k] = x0 + (k + 0.5) * bin;
  for (int k = 0; k < ny; ++k) r.top_y[k] = y0 + (k + 0.5) * bin;
  for (const CellSnapshot& c : cells) {
    const double top = c.z + half_h;
    if (!(top > 0.0)) continue;  // only ice above the waterline is seen
    const int ix = static_cast<int>(std::floor((c.x - x0) / bin));
    if (ix >= 0 && ix < nx) r.side_height[ix] = std::max(r.side_height[ix], top);
    const int iy = static_cast<int>(std::floor((c.y - y0) / bin));
    if (iy >= 0 && iy < ny && c.x > x0 && c.x < x1) r.top_extent[iy] = std::max(r.top_extent[iy], s.toe_x - c.x);
  }
  return r;
}

}  // namespace thin_ice
