#include "thin_ice_sim/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "thin_ice_sim/physics/pair_separation.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {
namespace {

constexpr double kPi = 3.14159265358979323846;

ModelConstants makeConstants(const Params& p, const IceSheet& sheet) {
  const IceParams& ice = p.ice;
  const double h = ice.thickness;
  const double regularisation = p.numerics.friction_regularisation;
  const double rate_limit = p.numerics.friction_viscous_limit / p.numerics.time_step;  // [1/s]
  ModelConstants c{};
  c.contact = {h,
               3.0 * ice.youngs_modulus / (1.0 - ice.poisson_ratio),
               3.0 * ice.vertical_modulus / (1.0 - ice.poisson_ratio),
               ice.smoothing_exponent_h,
               ice.smoothing_exponent_v,
               ice.friction_ice_ice,
               rate_limit,
               ice.compressive_strength,
               ice.contact_damping_ratio,
               regularisation};
  c.bond = {h,
            ice.smoothing_exponent_h,
            ice.smoothing_exponent_v,
            ice.flexural_strength,
            ice.compressive_strength,
            ice.compression_coupling,
            ice.youngs_modulus,
            ice.youngs_modulus / (2.0 * (1.0 + ice.poisson_ratio)),
            ice.vertical_modulus / (2.0 * (1.0 + ice.poisson_ratio)),
            ice.bond_damping_ratio};
  c.separation_gap_fraction = kSeparationGapFraction;
  c.water = {p.water.density,       p.water.gravity,        h, p.water.linear_drag,
             p.water.quadratic_drag, p.water.vertical_linear_drag, p.water.vertical_quadratic_drag};
  // The structure's friction is integrated at the sub-step dt/n (cell_forces.hpp).
  const double structure_rate_limit = rate_limit * p.numerics.structure_substeps;  // [1/s]
  c.structure = {p.structure.stiffness, h, p.structure.friction, ice.contact_damping_ratio, regularisation,
                 structure_rate_limit};
  c.pusher = {p.pusher.stiffness, h, p.pusher.friction, ice.contact_damping_ratio, regularisation, rate_limit};
  c.bottom = {p.bottom.stiffness, h, p.bottom.friction, ice.contact_damping_ratio, regularisation, rate_limit};
  c.wall = {p.channel.stiffness, h, p.channel.friction, ice.contact_damping_ratio, regularisation, rate_limit};

  // Face through (toe_x, 0, 0) rising towards +x at the given angle; outward normal towards the
  // ice: m = (-sin a, 0, cos a).
  const double angle = p.structure.angle_deg * kPi / 180.0;
  c.structure_face = {-std::sin(angle), 0.0, std::cos(angle), -std::sin(angle) * p.structure.toe_x};
  c.structure_top_z = p.structure.height;
  c.structure_toe_x = p.structure.toe_x;
  c.structure_y_min = -0.5 * p.structure.width;
  c.panels = p.structure.panels;
  c.panel_width = p.structure.width / p.structure.panels;
  c.calibration_factor = p.structure.calibration_factor;
  c.bottom_enabled = p.bottom.enabled;
  c.bottom_x_start = p.structure.toe_x - p.bottom.distance_from_structure;
  c.bottom_z = -p.bottom.depth;
  // Basin walls along the whole lane, or (without them) the side panels of the structure only.
  c.walls_enabled = true;
  if (p.channel.enabled) {
    c.wall_half_width = 0.5 * p.channel.width;
    c.wall_x_start = -1e30;
  } else {
    c.wall_half_width = 0.5 * p.structure.width;
    c.wall_x_start = p.structure.toe_x - p.structure.side_panel_length;
  }
  c.time_step = p.numerics.time_step;
  c.structure_substeps = p.numerics.structure_substeps;
  c.mean_edge_length = computeStats(sheet).mean_edge_length;
  if (!(c.mean_edge_length > 0.0)) c.mean_edge_length = p.sheet.cell_size;
  c.rebuild_displacement = p.numerics.rebuild_displacement * c.mean_edge_length;
  c.rebuild_rotation = p.numerics.rebuild_rotation_deg * kPi / 180.0;
  c.max_steps_between_rebuilds = p.numerics.max_steps_between_rebuilds;
  return c;
}

}  // namespace

Model buildModel(const Params& params, const IceSheet& sheet, const std::string& source) {
  Model m;
  const int n = static_cast<int>(sheet.cells.size());
  m.cell_count = n;
  m.vertex_x.assign(static_cast<size_t>(n) * kMaxPolygonVertices, 0.0);
  m.vertex_y.assign(static_cast<size_t>(n) * kMaxPolygonVertices, 0.0);
  m.vertex_count.resize(n);
  m.area.resize(n);
  m.mass.resize(n);
  m.inertia.resize(n);
  m.inverse_mass.resize(n);
  m.inverse_inertia.resize(n);
  m.polar_moment.resize(n);
  m.radius.resize(n);
  m.initial.resize(n);
  const IceParams& ice = params.ice;
  const double h = ice.thickness;
  const double z_float = floatingCentroidHeight(h, ice.density, params.water.density);
  double largest_radius = 0.0;
  for (int k = 0; k < n; ++k) {
    const CellGeometry& c = sheet.cells[k];
    m.vertex_count[k] = static_cast<int>(c.vertices.size());
    double r = 0.0;
    for (size_t v = 0; v < c.vertices.size(); ++v) {
      m.vertex_x[k * kMaxPolygonVertices + v] = c.vertices[v].x;
      m.vertex_y[k * kMaxPolygonVertices + v] = c.vertices[v].y;
      r = std::max(r, norm(c.vertices[v]));
    }
    m.area[k] = c.area;
    m.mass[k] = ice.density * c.area * h;
    m.inertia[k] = ice.density * h * c.polar_moment;
    m.inverse_mass[k] = 1.0 / m.mass[k];
    m.inverse_inertia[k] = 1.0 / m.inertia[k];
    m.polar_moment[k] = m.inertia[k] / (m.mass[k] / m.area[k]);
    m.radius[k] = r;
    largest_radius = std::max(largest_radius, r);
    m.initial[k] = {c.centroid.x, c.centroid.y, z_float, 0.0, 0.0, 0.0, 0.0, 0.0};
  }

  m.constants = makeConstants(params, sheet);
  for (const SharedEdge& e : sheet.edges) {
    const CellGeometry& ci = sheet.cells[e.i];
    const CellGeometry& cj = sheet.cells[e.j];
    BondShape b;
    const Vec2 mid = e.midpoint();
    b.anchor_i = mid - ci.centroid;
    b.anchor_j = mid - cj.centroid;
    b.edge_length = e.length;
    b.distance = norm(cj.centroid - ci.centroid);
    // Edge normal, turned to point from i to j.
    Vec2 normal = perpendicular((1.0 / e.length) * (e.end - e.start));
    if (dot(normal, cj.centroid - ci.centroid) < 0.0) normal = -normal;
    b.normal = normal;
    m.bond_i.push_back(e.i);
    m.bond_j.push_back(e.j);
    m.bond_rest.push_back(bondRestOf(b, m.mass[e.i], m.mass[e.j], m.constants.bond));
  }

  // Candidates: bounding circles closer than a margin that covers the motion allowed between
  // rebuilds (two cells each moving rebuild_displacement and turning rebuild_rotation).
  const ModelConstants& c = m.constants;
  const double margin = 2.0 * (c.rebuild_displacement + largest_radius * c.rebuild_rotation);
  m.constants.search_radius = 2.0 * largest_radius + margin;
  m.constants.search_margin = margin;

  if (2.0 * largest_radius >= (kMaxPanelsPerCell - 1) * c.panel_width) {
    std::ostringstream msg;
    msg << source << ": structure.panels = " << params.structure.panels << " makes panels "
        << c.panel_width << " m wide; allowed: panels at least "
        << 2.0 * largest_radius / (kMaxPanelsPerCell - 1) << " m wide (a cell may touch at most "
        << kMaxPanelsPerCell << " panels)";
    throw ScenarioError(msg.str());
  }
  m.initial_pusher_x = params.sheet.x_min;
  m.initial_pusher_velocity = params.pusher.velocity;
  const NumericsParams& numerics = params.numerics;
  const int substeps = numerics.structure_substeps;
  // With sub-steps the structure's spring is integrated at dt/n and the rest at dt; the sub-step
  // is checked against every spring at once (conservative: the held forces do not move in it).
  m.critical_time_step = criticalTimeStep(m, params, substeps == 1);
  m.structure_critical_time_step = substeps == 1 ? m.critical_time_step : criticalTimeStep(m, params, true);
  const double safety = numerics.critical_step_safety;
  const double allowed = safety * m.critical_time_step;
  const double allowed_substep = safety * m.structure_critical_time_step;
  // The least n that makes dt/n stable against the structure, and whether the loader accepts it.
  const long least_substeps = static_cast<long>(std::ceil(numerics.time_step / allowed_substep));
  const bool substeps_can_help = least_substeps <= kMaxStructureSubsteps;
  if (!(numerics.time_step <= allowed)) {
    std::ostringstream msg;
    msg << source << ": numerics.time_step = " << numerics.time_step << " s is unstable; allowed: <= " << allowed
        << " s (critical_step_safety " << safety << " x the critical step " << m.critical_time_step
        << " s of the stiffest spring"
        << (substeps == 1 ? "" : " other than the structure's, which numerics.structure_substeps subdivides")
        << "; it comes from ice.youngs_modulus, ice.vertical_modulus, ice.poisson_ratio, ice.thickness, ice.density, "
           "sheet.cell_size and the pusher's, the channel's and the bottom's stiffness)";
    // With one rate, say when sub-steps of the structure alone would make this dt stable.
    if (substeps == 1 && substeps_can_help) {
      const double ice_only = safety * criticalTimeStep(m, params, false);
      if (numerics.time_step <= ice_only) {
        msg << "; or keep it and set numerics.structure_substeps >= " << least_substeps
            << " (the structure's spring is what limits it)";
      }
    }
    throw ScenarioError(msg.str());
  }
  if (!(numerics.time_step / substeps <= allowed_substep)) {
    std::ostringstream msg;
    msg << source << ": numerics.structure_substeps = " << substeps << " leaves a sub-step of "
        << numerics.time_step / substeps << " s, unstable against the structure stiffness (structure.stiffness = "
        << params.structure.stiffness << " Pa); allowed: ";
    if (substeps_can_help) {
      msg << "numerics.structure_substeps >= " << least_substeps;
    } else {
      msg << "a smaller numerics.time_step (it would need more than " << kMaxStructureSubsteps << " sub-steps)";
    }
    msg << " (sub-step <= critical_step_safety " << safety << " x " << m.structure_critical_time_step << " s)";
    throw ScenarioError(msg.str());
  }
  return m;
}

double criticalTimeStep(const Model& m, const Params& p, bool with_structure) {
  // Per cell: the sum of the stiffnesses that can act on it at once, against its mass and (through
  // the moment arm of its radius) its yaw inertia.
  std::vector<double> bond_stiffness(m.cell_count, 0.0);
  for (size_t b = 0; b < m.bond_rest.size(); ++b) {
    const BondRest& r = m.bond_rest[b];
    const double k = std::max({r.k_normal, r.k_shear, r.k_vertical});
    bond_stiffness[m.bond_i[b]] += k;
    bond_stiffness[m.bond_j[b]] += k;
  }
  const ModelConstants& c = m.constants;
  const double contact_stiffness = c.contact.plane_modulus * p.ice.thickness;
  double omega_max = 0.0;
  for (int k = 0; k < m.cell_count; ++k) {
    // Plane laws: an edge about one cell wide flush with the plane, S_pen = width x depth.
    const double width = std::sqrt(m.area[k]);
    const double structure = with_structure ? p.structure.stiffness : 0.0;
    const double plane = std::max({structure, p.pusher.stiffness, p.channel.stiffness, p.bottom.stiffness}) * width;
    // Cell-cell springs (a broken cell touches about six neighbours in place of its bonds) count
    // twice, since the neighbour may move the other way; a rigid plane does not move.
    const double k_sum = 2.0 * std::max(bond_stiffness[k], 6.0 * contact_stiffness) + plane;
    const double translation = k_sum / m.mass[k];
    const double rotation = k_sum * m.radius[k] * m.radius[k] / m.inertia[k];
    omega_max = std::max(omega_max, std::sqrt(std::max(translation, rotation)));
  }
  const double zeta = std::max(p.ice.contact_damping_ratio, p.ice.bond_damping_ratio);
  return omega_max > 0.0 ? 2.0 / omega_max * (std::sqrt(1.0 + zeta * zeta) - zeta) : 0.0;
}

}  // namespace thin_ice
