// A field of free cells for the contact tests: a model's bonds removed and every cell displaced by
// up to 1 mm, turned by up to 0.02 rad and set moving at up to 0.2 m/s and 1 rad/s, so that
// neighbours overlap, collide and part again.
#pragma once

#include <random>

#include "thin_ice_sim/model.hpp"

namespace thin_ice {
namespace testing {

/// Makes `model` a field of free, jostled cells (the same field for the same seed).
inline void jostleFreeCells(Model& model, unsigned seed) {
  model.bond_i.clear();
  model.bond_j.clear();
  model.bond_rest.clear();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (CellMotion& m : model.initial) {
    m.x += 1e-3 * unit(random);
    m.y += 1e-3 * unit(random);
    m.yaw += 0.02 * unit(random);
    m.vx = 0.2 * unit(random);
    m.vy = 0.2 * unit(random);
    m.wz = 1.0 * unit(random);
  }
}

}  // namespace testing
}  // namespace thin_ice
