#include "thin_ice_sim/study/front_row_balance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thin_ice {

FrontRow frontRow(const Model& model, const IceSheet& sheet) {
  // A cell is in the front row when one of its vertices lies on the front edge (to 1 nm: the
  // sheet's polygons are clipped to the rectangle, so those vertices sit on it up to rounding).
  const double front = sheet.spec.x_min + sheet.spec.length;
  constexpr double kOnEdge = 1e-9;  // [m]
  std::vector<char> in_front(sheet.cells.size(), 0);
  FrontRow row;
  for (size_t k = 0; k < sheet.cells.size(); ++k) {
    const CellGeometry& c = sheet.cells[k];
    double max_x = -INFINITY;
    for (const Vec2& v : c.vertices) max_x = std::max(max_x, c.centroid.x + v.x);
    if (max_x <= front - kOnEdge) continue;
    in_front[k] = 1;
    row.cells.push_back(static_cast<int>(k));
    row.area += model.area[k];
    row.weight += model.mass[k] * model.constants.water.gravity;
  }
  std::vector<char> is_rear(sheet.cells.size(), 0);
  for (size_t b = 0; b < model.bond_rest.size(); ++b) {
    const int i = model.bond_i[b], j = model.bond_j[b];
    if (in_front[i] == in_front[j]) continue;
    row.cut_bonds.push_back(static_cast<int>(b));
    is_rear[in_front[i] ? j : i] = 1;
  }
  for (size_t k = 0; k < is_rear.size(); ++k) {
    if (is_rear[k]) row.rear_cells.push_back(static_cast<int>(k));
  }
  return row;
}

namespace {

BodyState restingBody(const Model& model, const CellPose& pose, int k) {
  BodyState b{};
  b.centroid = {pose.x, pose.y};
  b.z = pose.z;
  b.mass = model.mass[k];
  b.inertia = model.inertia[k];
  return b;
}

double waterLift(const Model& model, int k, double z) {
  // Polar moment J = inertia / (rho h): it only scales the yaw drag, which is zero at rest.
  return waterForce(model.constants.water, model.mass[k], model.area[k], 0.0, z, {0.0, 0.0}, 0.0, 0.0).vertical;
}

double meanLift(const Model& model, const std::vector<int>& cells, const std::vector<CellPose>& poses) {
  if (cells.empty()) return 0.0;
  double sum = 0.0;
  for (int k : cells) sum += poses[k].z - model.initial[k].z;
  return sum / static_cast<double>(cells.size());
}

}  // namespace

FrontRowBalance frontRowBalance(const Model& model, const FrontRow& row, const std::vector<CellPose>& poses) {
  if (poses.size() != static_cast<size_t>(model.cell_count)) {
    throw std::invalid_argument("frontRowBalance: " + std::to_string(poses.size()) + " cell poses for a model of " +
                                std::to_string(model.cell_count) + " cells");
  }
  std::vector<char> in_front(model.cell_count, 0);
  for (int k : row.cells) in_front[k] = 1;
  FrontRowBalance balance;
  for (int b : row.cut_bonds) {
    const int i = model.bond_i[b], j = model.bond_j[b];
    const BodyState body_i = restingBody(model, poses[i], i), body_j = restingBody(model, poses[j], j);
    const Vec2 turn_i{std::cos(poses[i].yaw), std::sin(poses[i].yaw)};
    const Vec2 turn_j{std::cos(poses[j].yaw), std::sin(poses[j].yaw)};
    const BondForce f = rmibBondForce(model.bond_rest[b], body_i, turn_i, body_j, turn_j, model.constants.bond);
    const double up_on_front = in_front[j] ? f.fz_on_j : -f.fz_on_j;
    balance.bond_force -= up_on_front;
  }
  for (int k : row.cells) balance.lost_buoyancy += waterLift(model, k, model.initial[k].z) - waterLift(model, k, poses[k].z);
  balance.front_lift = meanLift(model, row.cells, poses);
  balance.rear_lift = meanLift(model, row.rear_cells, poses);
  return balance;
}

}  // namespace thin_ice
