// The model a backend steps: fixed cell geometry, bond rest data and the constants of every law,
// built once from Params and the sheet (data flows scenario -> params + sheet -> model -> backend).
#pragma once

#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/params.hpp"
#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/physics/cell_forces.hpp"
#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/plane_contact.hpp"
#include "thin_ice_sim/physics/water.hpp"

namespace thin_ice {

struct Model {
  int cell_count = 0;
  // Cell geometry, (cells x kMaxPolygonVertices) body-frame vertex offsets [m] about the centroid.
  std::vector<double> vertex_x, vertex_y;
  std::vector<int> vertex_count;        ///< (cells)
  std::vector<double> area;             ///< (cells) [m^2]
  std::vector<double> mass;             ///< (cells) [kg]
  std::vector<double> inertia;          ///< (cells) yaw inertia rho h J [kg m^2]
  // Derived once here so that no step divides by them: 1 / mass [1/kg], 1 / inertia
  // [1/(kg m^2)] and inertia / (mass / area) [m^4] (the second moment of area of the yaw drag,
  // Eq. 16), each computed by the same expression the step used to evaluate, so the results do
  // not change by a bit.
  std::vector<double> inverse_mass, inverse_inertia, polar_moment;
  std::vector<double> radius;           ///< (cells) farthest vertex from the centroid [m]
  // Bonds, (bonds): the two cells (i < j) and what they remember from t = 0.
  std::vector<int> bond_i, bond_j;
  std::vector<BondRest> bond_rest;
  // Initial state.
  std::vector<CellMotion> initial;      ///< (cells) at rest at the floating draft
  double initial_pusher_x = 0.0;        ///< [m]
  double initial_pusher_velocity = 0.0; ///< [m/s]
  ModelConstants constants{};
  double critical_time_step = 0.0;      ///< [s] of the stiffest spring stepped with dt, damping included
  double structure_critical_time_step = 0.0;  ///< [s] with the structure's spring too (bounds dt/n)
};

/// Builds the model. Throws ScenarioError (numerics.time_step) when dt exceeds
/// critical_step_safety x the critical time step, or (numerics.structure_substeps) when the
/// sub-step dt/n does so with the structure's spring counted.
Model buildModel(const Params& params, const IceSheet& sheet, const std::string& source);

/// Critical time step [s] of the model's stiffest spring (bonds, contacts, pusher, walls, bottom,
/// and the structure when with_structure), for symplectic Euler with damping ratio zeta:
/// dt_c = (2 / omega_max)(sqrt(1 + zeta^2) - zeta).
double criticalTimeStep(const Model& model, const Params& params, bool with_structure = true);

}  // namespace thin_ice
