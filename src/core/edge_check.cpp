#include "thin_ice_sim/edge_check.hpp"

#include <cmath>
#include <stdexcept>

namespace thin_ice {

BondVerticalCapacity bondVerticalCapacity(const BondRest& rest, const BondConstants& constants, int samples) {
  if (samples < 2) throw std::invalid_argument("bondVerticalCapacity: samples must be >= 2");
  // Cell i at the origin, cell j placed so that the two anchors coincide (no horizontal strain);
  // both at rest and unturned, so only the vertical spring of Eq. (12) is loaded.
  BodyState i{};
  BodyState j{};
  j.centroid = rest.anchor_i - rest.anchor_j;
  const Vec2 unturned{1.0, 0.0};
  const auto force_at = [&](double dz, bool& breaks) {
    j.z = dz;
    const BondForce f = rmibBondForce(rest, i, unturned, j, unturned, constants);
    breaks = f.breaks;
    return std::fabs(f.fz_on_j);
  };
  BondVerticalCapacity capacity;
  double intact_dz = 0.0;
  for (int s = 1; s <= samples; ++s) {
    const double dz = constants.thickness * s / samples;
    bool breaks = false;
    const double force = force_at(dz, breaks);
    if (!breaks) {
      capacity.force = std::fmax(capacity.force, force);
      intact_dz = dz;
      continue;
    }
    // The threshold lies between the last intact sample and this one: bisect it, so that a bond
    // that fails early (stiff E_v) is not under-read by a whole sampling step.
    double broken_dz = dz;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (intact_dz + broken_dz);
      bool mid_breaks = false;
      const double mid_force = force_at(mid, mid_breaks);
      if (mid_breaks) {
        broken_dz = mid;
      } else {
        capacity.force = std::fmax(capacity.force, mid_force);
        intact_dz = mid;
      }
    }
    capacity.offset = broken_dz;
    capacity.by_stress = broken_dz < constants.thickness;
    return capacity;
  }
  capacity.offset = constants.thickness;  // |dz| = h always tears the bond (bondFails)
  return capacity;
}

FloatingPlateEdge floatingPlateEdge(const IceParams& ice, const WaterParams& water) {
  const double h = ice.thickness, E = ice.youngs_modulus;
  const double foundation = water.density * water.gravity;  // rho_w g [N/m^3]
  FloatingPlateEdge plate;
  plate.characteristic_length = floatingPlateLength(E, ice.poisson_ratio, h, water.density, water.gravity);
  plate.critical_line_load = 0.665 * ice.flexural_strength * std::pow(foundation * std::pow(h, 5) / E, 0.25);
  return plate;
}

std::vector<EdgeCutCapacity> edgeCutCapacities(const Model& model, const IceSheet& sheet, int cuts) {
  const double front = sheet.spec.x_min + sheet.spec.length;
  std::vector<BondVerticalCapacity> capacity(model.bond_rest.size());
  for (size_t b = 0; b < capacity.size(); ++b) capacity[b] = bondVerticalCapacity(model.bond_rest[b], model.constants.bond);
  std::vector<EdgeCutCapacity> out;
  for (int k = 1; k <= cuts; ++k) {
    EdgeCutCapacity cut;
    cut.distance_from_edge = k * sheet.spec.cell_size;
    const double x_cut = front - cut.distance_from_edge;
    for (size_t b = 0; b < capacity.size(); ++b) {
      const double xi = sheet.cells[model.bond_i[b]].centroid.x, xj = sheet.cells[model.bond_j[b]].centroid.x;
      if ((xi < x_cut) == (xj < x_cut)) continue;
      ++cut.bonds;
      if (capacity[b].by_stress) ++cut.failing_by_stress;
      cut.line_load += capacity[b].force;
    }
    cut.line_load /= sheet.spec.width;
    out.push_back(cut);
  }
  return out;
}

}  // namespace thin_ice
