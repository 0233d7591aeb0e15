#include "thin_ice_sim/study/edge_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thin_ice {

BondForce bondUnderOffset(const BondRest& rest, const BondConstants& constants, double dz) {
  // Cell i at the origin, cell j placed so that the two anchors coincide (no horizontal strain);
  // both at rest and unturned, so only the vertical spring of Eq. (12) is loaded.
  BodyState i{};
  BodyState j{};
  j.centroid = rest.anchor_i - rest.anchor_j;
  j.z = dz;
  const Vec2 unturned{1.0, 0.0};
  return rmibBondForce(rest, i, unturned, j, unturned, constants);
}

double bondVerticalForce(const BondRest& rest, const BondConstants& constants, double dz, bool& breaks) {
  const BondForce f = bondUnderOffset(rest, constants, dz);
  breaks = f.breaks;
  return std::fabs(f.fz_on_j);
}

LargestVerticalStress largestVerticalStress(const BondRest& rest, const BondConstants& constants, int samples) {
  if (samples < 2) throw std::invalid_argument("largestVerticalStress: samples must be >= 2");
  const double h = constants.thickness;
  const auto stress = [&](double dz) { return bondUnderOffset(rest, constants, dz).sigma_v; };
  int best = 1;
  double best_stress = stress(h / samples);
  for (int s = 2; s < samples; ++s) {
    const double value = stress(h * s / samples);
    if (value > best_stress) {
      best_stress = value;
      best = s;
    }
  }
  // The top lies within one sample of the best one: golden-section search there.
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double low = h * (best - 1) / samples, high = h * std::min(best + 1, samples) / samples;
  for (int k = 0; k < 80; ++k) {
    const double left = high - ratio * (high - low), right = low + ratio * (high - low);
    if (stress(left) < stress(right)) {
      low = left;
    } else {
      high = right;
    }
  }
  const double refined = 0.5 * (low + high);
  const double refined_stress = stress(refined);
  LargestVerticalStress top;
  top.stress = refined_stress >= best_stress ? refined_stress : best_stress;
  top.offset = refined_stress >= best_stress ? refined : h * best / samples;
  return top;
}

int bondNearestLength(const Model& model, double distance) {
  int nearest = -1;
  for (size_t b = 0; b < model.bond_rest.size(); ++b) {
    if (nearest < 0 || std::fabs(model.bond_rest[b].distance - distance) <
                           std::fabs(model.bond_rest[nearest].distance - distance)) {
      nearest = static_cast<int>(b);
    }
  }
  return nearest;
}

BondVerticalCapacity bondVerticalCapacity(const BondRest& rest, const BondConstants& constants, int samples) {
  if (samples < 2) throw std::invalid_argument("bondVerticalCapacity: samples must be >= 2");
  BondVerticalCapacity capacity;
  double intact_dz = 0.0;
  for (int s = 1; s <= samples; ++s) {
    const double dz = constants.thickness * s / samples;
    bool breaks = false;
    const double force = bondVerticalForce(rest, constants, dz, breaks);
    if (!breaks) {
      capacity.force = std::fmax(capacity.force, force);
      intact_dz = dz;
      continue;
    }
    // The threshold lies between the last intact sample and this one: bisect it.
    double broken_dz = dz;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (intact_dz + broken_dz);
      bool mid_breaks = false;
      const double mid_force = bondVerticalForce(rest, constants, mid, mid_breaks);
      if (mid_breaks) {
        broken_dz = mid;
      } else {
        capacity.force = std::fmax(capacity.force, mid_force);
        intact_dz = mid;
      }
    }
    capacity.offset = broken_dz;
    capacity.last_intact = intact_dz;
    capacity.by_stress = broken_dz < constants.thickness;
    return capacity;
  }
  capacity.offset = constants.thickness;  // |dz| = h always tears the bond (bondFails)
  capacity.last_intact = intact_dz;
  return capacity;
}

FloatingPlateEdge floatingPlateEdge(const IceParams& ice, const WaterParams& water) {
  const double h = ice.thickness;
  FloatingPlateEdge plate;
  plate.characteristic_length =
      floatingPlateLength(ice.youngs_modulus, ice.poisson_ratio, h, water.density, water.gravity);
  // sigma_f = 6 M_max / h^2 with M_max = P x the plate's moment arm.
  const double arm = floatingPlateMomentArm(ice.youngs_modulus, ice.poisson_ratio, h, water.density, water.gravity);
  plate.critical_line_load = ice.flexural_strength * h * h / (6.0 * arm);
  return plate;
}

std::vector<EdgeCutCapacity> edgeCutCapacities(const Model& model, const IceSheet& sheet, int cuts) {
  const BondConstants& law = model.constants.bond;
  const double front = sheet.spec.x_min + sheet.spec.length;
  std::vector<BondVerticalCapacity> capacity(model.bond_rest.size());
  for (size_t b = 0; b < capacity.size(); ++b) capacity[b] = bondVerticalCapacity(model.bond_rest[b], law);
  constexpr int kSamples = 4000;  // common offsets of the rigid strip, 0 < dz < h
  std::vector<EdgeCutCapacity> out;
  for (int k = 1; k <= cuts; ++k) {
    EdgeCutCapacity cut;
    cut.distance_from_edge = k * sheet.spec.cell_size;
    const double x_cut = front - cut.distance_from_edge;
    std::vector<size_t> crossing;
    for (size_t b = 0; b < capacity.size(); ++b) {
      const double xi = sheet.cells[model.bond_i[b]].centroid.x, xj = sheet.cells[model.bond_j[b]].centroid.x;
      if ((xi < x_cut) == (xj < x_cut)) continue;
      crossing.push_back(b);
      if (capacity[b].by_stress) ++cut.failing_by_stress;
      cut.sum_of_peaks += capacity[b].force;
    }
    cut.bonds = static_cast<int>(crossing.size());
    // The strip's offsets: a grid (for peaks inside the sweep) and each bond's last intact offset
    // (for failures by stress, where a bond's force is largest).
    std::vector<double> offsets;
    for (int s = 1; s < kSamples; ++s) offsets.push_back(law.thickness * s / kSamples);
    for (size_t b : crossing) offsets.push_back(capacity[b].last_intact);
    double best = 0.0;
    for (double dz : offsets) {
      double total = 0.0;
      for (size_t b : crossing) {
        if (dz > capacity[b].last_intact) continue;  // failed at a smaller offset
        bool breaks = false;
        total += bondVerticalForce(model.bond_rest[b], law, dz, breaks);
      }
      best = std::fmax(best, total);
    }
    cut.line_load = best / sheet.spec.width;
    cut.sum_of_peaks /= sheet.spec.width;
    out.push_back(cut);
  }
  return out;
}

}  // namespace thin_ice
