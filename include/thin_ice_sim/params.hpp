// Parameters of one simulation: read-only while it runs (as MuJoCo's mjModel). Every field has
// its unit; defaults are those of the medium-ice experiment M-2 (paper Tables 4 and 5) and live
// here only. Scenario files (config/scenarios/*.yaml) set them; scenario.cpp validates them.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "thin_ice_sim/ice_sheet.hpp"

namespace thin_ice {

struct IceParams {
  double thickness = 0.051;             ///< h [m]
  double density = 920.0;               ///< rho_i [kg/m^3]
  double flexural_strength = 108e3;     ///< sigma_f [Pa]
  double compressive_strength = 130e3;  ///< sigma_comp [Pa]
  double youngs_modulus = 328e6;        ///< E [Pa], horizontal
  double vertical_modulus = 328e6;      ///< E_v [Pa]
  /// E_v as a multiple of the floating plate's (physics/bond.hpp, floatingPlateVerticalModulus)
  /// [-]; NaN: E_v is given as a value. The loader works E_v out from it (scenario.cpp).
  double vertical_modulus_floating_plate_multiple = std::numeric_limits<double>::quiet_NaN();
  double poisson_ratio = 0.3;           ///< nu [-], in [0, 0.5)
  double smoothing_exponent_h = 1.0;    ///< n of K_n (Eq. 6) for horizontal forces [-]
  double smoothing_exponent_v = 1.0;    ///< n of K_v (Eq. 6) for vertical forces [-]
  double compression_coupling = 0.0;    ///< k of Eq. (13) [-]
  /// k as a fraction of sigma_f / sigma_comp (the paper: k ~ sigma_f / sigma_comp) [-]; NaN: k is
  /// given as a value. The loader works k out from it (scenario.cpp).
  double compression_coupling_strength_fraction = std::numeric_limits<double>::quiet_NaN();
  double friction_ice_ice = 0.3;        ///< Coulomb coefficient between cells [-]
  double contact_damping_ratio = 0.2;   ///< zeta of DEM contacts (fraction of critical) [-]
  double bond_damping_ratio = 0.2;      ///< zeta of RMIB bonds [-]
};

struct WaterParams {
  double density = 1000.0;          ///< rho_w [kg/m^3]
  double gravity = 9.81;            ///< g [m/s^2]
  double linear_drag = 20.0;        ///< horizontal skin drag per wetted area [N s/m^3]
  double quadratic_drag = 0.5;      ///< horizontal quadratic drag coefficient (x 0.5 rho_w A) [-]
  double vertical_linear_drag = 200.0;  ///< heave drag per area [N s/m^3]
  double vertical_quadratic_drag = 1.0; ///< heave quadratic drag coefficient [-]
};

/// The false bottom of the shallow-water tests: a horizontal plane at depth, from x_start on.
struct BottomParams {
  bool enabled = true;
  double distance_from_structure = 4.0;  ///< [m] the bottom starts this far in front of the toe
  double depth = 0.25;              ///< [m] water depth over the false bottom (not in the paper)
  double friction = 0.55;           ///< ice-bottom Coulomb coefficient (Table 4) [-]
  double stiffness = 1e8;           ///< penalty K_bottom [Pa]: force = K S_pen (as Eq. 17)
};

/// The inclined structure (Table 4): a plane face rising towards +x from its toe at the
/// waterline, split into panels across y, with side panels guiding the rubble.
struct StructureParams {
  double toe_x = 20.0;              ///< [m] x where the face crosses the waterline z = 0
  double angle_deg = 60.0;          ///< inclination from horizontal [deg]
  double width = 10.0;              ///< [m] across y, centred on y = 0
  double height = 1.0;              ///< [m] top of the face above the waterline
  int panels = 10;                  ///< panels across the width, each reports its load
  double side_panel_length = 0.5;   ///< [m] vertical side plates reaching forward from the toe
  double stiffness = 1.7e11;        ///< K_struct of Eq. (17) [Pa]
  double calibration_factor = 1.0;  ///< alpha of Eq. (18) [-]; 1: the load does not depend on K_struct
  double friction = 0.1;            ///< ice-structure Coulomb coefficient [-]
};

/// x [m] of the structure face at height z [m]: it crosses the waterline at toe_x and rises
/// towards +x at angle_deg from horizontal.
inline double structureFaceX(const StructureParams& s, double z) {
  return s.toe_x + z / std::tan(s.angle_deg * 3.14159265358979323846 / 180.0);
}

/// The pushing plate: a vertical plate across the basin, normal +x.
struct PusherParams {
  double velocity = 0.05;           ///< [m/s] towards +x (the structure); Table 4
  double stiffness = 1e9;           ///< penalty [Pa], force = K S_pen as for the structure
  double friction = 0.0;            ///< [-] ice-plate Coulomb coefficient; 0: a smooth plate
};

/// Walls along the basin's long sides (y = +-channel_width/2), so the sheet stays in the lane.
struct ChannelParams {
  bool enabled = true;
  double width = 10.0;              ///< [m] distance between the walls
  double stiffness = 1e9;           ///< penalty [Pa]; also the side panels' when enabled is false
  double friction = 0.1;            ///< [-]; also the side panels' when enabled is false
};

/// Largest numerics.structure_substeps the loader accepts.
constexpr int kMaxStructureSubsteps = 1000;

struct NumericsParams {
  double time_step = 5e-6;          ///< dt [s]; refused above the critical step
  double critical_step_safety = 0.8;///< dt must be <= this x the critical step of the stiffest spring
                                    ///< (the structure's against dt / structure_substeps)
                                    ///< (in (0, 1]; up to 1000 only to provoke a blow-up in tests)
  int max_steps_between_rebuilds = 1000;  ///< N_iter of Algorithm 1
  int structure_substeps = 1;       ///< n [-]: a cell that can reach the structure takes n steps of
                                    ///< dt/n against it, the other forces held (physics/cell_forces.hpp);
                                    ///< 1 .. kMaxStructureSubsteps
  double rebuild_displacement = 0.1;      ///< rebuild when a cell moved this x l-bar [-]
  double rebuild_rotation_deg = 2.0;      ///< ... or turned this much [deg] (delta_rot)
  double friction_regularisation = 1e-3;  ///< [m/s] slip speed below which friction is viscous
  double friction_viscous_limit = 0.5;    ///< beta [-]: viscous friction <= beta m_eff / dt (stable for < 2)
  int threads = 0;                  ///< OpenMP threads on the CPU; 0 = all cores from 2000 cells up, one below
};

struct Params {
  IceParams ice;
  IceSheetSpec sheet;
  WaterParams water;
  BottomParams bottom;
  StructureParams structure;
  PusherParams pusher;
  ChannelParams channel;
  NumericsParams numerics;
};

}  // namespace thin_ice
