// CPU backend. One step (Algorithm 1, inner loop body):
//   world polygons and bounding boxes of every cell          (parallel over cells)
//   RMIB bond forces and failure (cpu_bond_pass.cpp)          (parallel over bonds)   Eqs. 8-13
//   DEM contact forces of the candidate pairs                 (parallel over pairs)   Eqs. 1-4
//     (a pair kept apart by an edge found in an earlier step skips the clip: pair_separation.hpp)
//   per cell: gather bond and contact forces in a fixed order, water, structure, pusher,
//   bottom and walls, then symplectic Euler                   (parallel over cells)   Eqs. 14-17
//   structure loads summed in cell order                      (serial, touching cells only)
//   rebuild the candidate pairs when a cell moved > 0.1 l-bar, turned > delta_rot, a bond broke,
//   or N_iter steps passed                                    (Algorithm 1, lines 14-17)
//                                                             (parallel over ranges of cells and of candidates)
// Pair forces are stored per pair and gathered per cell through fixed index lists, so the result
// is bit-identical for any number of threads.
#include "cpu_backend.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cpu_bond_pass.hpp"
#include "thin_ice_sim/incidence.hpp"
#include "thin_ice_sim/neighbour_search.hpp"
#include "thin_ice_sim/physics/pair_separation.hpp"

namespace thin_ice {
namespace {

constexpr int kV = kMaxPolygonVertices;
/// With threads = 0 (automatic), below this many cells the loops run on one thread: the fork-join of a parallel loop costs
/// microseconds, more than a small scene's whole step (measured: a 20-cell strip ran 10x slower
/// on two threads than on one).
constexpr int kMinCellsForThreads = 2000;


class CpuBackend final : public Backend {
 public:
  CpuBackend(const Model& model, int threads)
      : model_(model),
        // More threads than the cores present only queue up behind each other at every loop's
        // barrier (numerics.threads = 1000 ended in a libgomp abort): capped at the cores.
        threads_(threads > 0 ? std::min(threads, omp_get_num_procs()) : omp_get_max_threads()),
        parallel_(threads_ > 1 && (threads > 0 || model.cell_count >= kMinCellsForThreads)),
        bond_pass_(model) {
    const int n = model_.cell_count;
    world_.resize(static_cast<size_t>(n) * kV);
    turn_.resize(n);
    box_.resize(static_cast<size_t>(n) * 4);
    structure_.resize(n);
    pusher_fx_.resize(n);
    loaded_.assign(n, 0);
    subcycled_.assign(n, 0);
    held_.resize(n);
    subcycled_cells_.reserve(n);
    bond_load_.resize(model_.bond_rest.size());
    bond_incidence_.build(n, model_.bond_i, model_.bond_j);
    reset();
  }

  std::string name() const override { return "cpu"; }

  void reset() override {
    motion_ = model_.initial;
    bond_state_.assign(model_.bond_rest.size(), kBondIntact);
    broken_count_ = 0;
    time_ = 0.0;
    steps_ = 0;
    pusher_x_ = model_.initial_pusher_x;
    health_error_.clear();
    loads_ = LoadSample{};
    // No S_ref carried into the new run (the CUDA backend clears its list likewise).
    contact_i_.clear();
    contact_j_.clear();
    contact_reference_.clear();
    contact_separating_edge_.clear();
    rebuild_requested_ = true;
  }

  void step(long steps, double pusher_velocity) override {
    const ModelConstants& c = model_.constants;
    LoadSample sum;
    sum.panel_horizontal.assign(c.panels, 0.0);
    sum.panel_vertical.assign(c.panels, 0.0);
    sum.panel_lateral.assign(c.panels, 0.0);
    sum.panel_torque.assign(c.panels, Torque3{});
    long taken = 0;
    for (long s = 0; s < steps && health_error_.empty(); ++s) {
      if (rebuild_requested_) rebuildContacts();
      stepOnce(pusher_velocity, sum);
      ++taken;
    }
    averageSummedLoads(sum, taken, c.calibration_factor);
    sum.time = time_;
    sum.pushed_length = pusher_x_ - model_.initial_pusher_x;
    sum.broken_bonds = broken_count_;
    sum.intact_bonds = static_cast<int>(model_.bond_rest.size()) - broken_count_;
    sum.contacts = last_contacts_;
    loads_ = sum;
  }

  double time() const override { return time_; }
  long stepCount() const override { return steps_; }
  double pusherPosition() const override { return pusher_x_; }
  LoadSample loads() const override { return loads_; }
  std::string healthError() const override { return health_error_; }

  std::vector<CellSnapshot> cells() const override {
    return makeCellSnapshots(model_, motion_, bond_state_);
  }

  long pairsKeptApart() const override {
    return static_cast<long>(contact_separating_edge_.size()) -
           std::count(contact_separating_edge_.begin(), contact_separating_edge_.end(), kNoSeparatingEdge);
  }

  BackendState saveState() const override {
    BackendState s;
    s.time = time_;
    s.steps = steps_;
    s.pusher_x = pusher_x_;
    s.motion = motion_;
    s.bond_state = bond_state_;  // kBondBreaking lasts only inside a step on the CPU
    s.contact_i = contact_i_;
    s.contact_j = contact_j_;
    s.contact_reference = contact_reference_;
    return s;
  }

  void restoreState(const BackendState& s) override {
    reset();
    time_ = s.time;
    steps_ = s.steps;
    pusher_x_ = s.pusher_x;
    motion_ = s.motion;
    bond_state_ = s.bond_state;
    broken_count_ = countBrokenBonds(bond_state_);
    // The saved pairs are the list the first rebuild carries S_ref from (rebuild_requested_ is set).
    contact_i_ = s.contact_i;
    contact_j_ = s.contact_j;
    contact_reference_ = s.contact_reference;
  }

 private:
  BodyState body(int k) const {
    return bodyOf(motion_[k], model_.mass[k], model_.inertia[k]);
  }

  /// Candidate pairs within the search radius that are not held by an intact bond.
  void rebuildContacts() {
    const int n = model_.cell_count;
    std::vector<Vec2> centres(n);
    for (int k = 0; k < n; ++k) centres[k] = {motion_[k].x, motion_[k].y};
    const int ranges = parallel_ ? threads_ : 1;
    const std::vector<CandidatePair>& candidates =
        search_.findPairs(centres, model_.constants.search_radius, ranges);
    // The pairs come sorted by (i, j); the pairs that stay keep their reference overlap S_ref,
    // a new pair gets -1: its overlap at its first step becomes S_ref (contact.hpp). The
    // candidates are filtered in contiguous ranges, in parallel, and joined in order.
    previous_i_.swap(contact_i_);
    previous_j_.swap(contact_j_);
    previous_reference_.swap(contact_reference_);
    previous_separating_edge_.swap(contact_separating_edge_);
    kept_ranges_.resize(ranges);
    const long candidate_count = static_cast<long>(candidates.size());
#pragma omp parallel for num_threads(ranges) schedule(static, 1) if (ranges > 1)
    for (int t = 0; t < ranges; ++t) {
      keepContactPairs(candidates, centres, candidate_count * t / ranges, candidate_count * (t + 1) / ranges,
                       kept_ranges_[t]);
    }
    contact_i_.clear();
    contact_j_.clear();
    contact_reference_.clear();
    contact_separating_edge_.clear();
    for (const KeptPairs& range : kept_ranges_) {
      contact_i_.insert(contact_i_.end(), range.i.begin(), range.i.end());
      contact_j_.insert(contact_j_.end(), range.j.begin(), range.j.end());
      contact_reference_.insert(contact_reference_.end(), range.reference.begin(), range.reference.end());
      contact_separating_edge_.insert(contact_separating_edge_.end(), range.separating_edge.begin(),
                                      range.separating_edge.end());
    }
    contact_touching_.resize(contact_i_.size());
    contact_load_.resize(contact_i_.size());
    contact_incidence_.build(n, contact_i_, contact_j_);
    reference_ = motion_;
    steps_since_rebuild_ = 0;
    rebuild_requested_ = false;
  }

  /// The contact pairs of one range of candidates (they are sorted by (i, j)).
  struct KeptPairs {
    std::vector<int> i, j;
    std::vector<double> reference;  ///< S_ref carried from the previous list, -1: new
    std::vector<int> separating_edge;  ///< carried likewise, kNoSeparatingEdge: new
  };

  /// Candidates [first, end) whose bounding circles (radius r + margin) can meet before the next
  /// rebuild and that no intact bond holds, with the S_ref they had in the previous list.
  void keepContactPairs(const std::vector<CandidatePair>& candidates, const std::vector<Vec2>& centres, long first,
                        long end, KeptPairs& out) const {
    out.i.clear();
    out.j.clear();
    out.reference.clear();
    out.separating_edge.clear();
    if (first >= end) return;
    const double margin = model_.constants.search_margin;
    // The previous list is sorted by (i, j) too: start at its first pair of this range's first i
    // (the walk below passes the ones with a smaller j).
    size_t cursor = static_cast<size_t>(
        std::lower_bound(previous_i_.begin(), previous_i_.end(), candidates[first].i) - previous_i_.begin());
    for (long c = first; c < end; ++c) {
      const CandidatePair& p = candidates[c];
      const double reach = model_.radius[p.i] + model_.radius[p.j] + margin;
      const double dx = centres[p.j].x - centres[p.i].x, dy = centres[p.j].y - centres[p.i].y;
      if (dx * dx + dy * dy > reach * reach) continue;
      if (hasIntactBond(p.i, p.j)) continue;
      while (cursor < previous_i_.size() &&
             (previous_i_[cursor] < p.i || (previous_i_[cursor] == p.i && previous_j_[cursor] < p.j))) {
        ++cursor;
      }
      const bool kept = cursor < previous_i_.size() && previous_i_[cursor] == p.i && previous_j_[cursor] == p.j;
      out.i.push_back(p.i);
      out.j.push_back(p.j);
      out.reference.push_back(kept ? previous_reference_[cursor] : -1.0);
      // After restoreState the saved pairs come without their edges (a hint, not state).
      const bool known = kept && cursor < previous_separating_edge_.size();
      out.separating_edge.push_back(known ? previous_separating_edge_[cursor] : kNoSeparatingEdge);
    }
  }

  bool hasIntactBond(int i, int j) const {
    for (int e = bond_incidence_.offsets[i]; e < bond_incidence_.offsets[i + 1]; ++e) {
      const int b = bond_incidence_.entries[e] >> 1;
      if (bond_state_[b] == kBondIntact && (model_.bond_i[b] == j || model_.bond_j[b] == j)) return true;
    }
    return false;
  }

  void updateWorldPolygons() {
    const int n = model_.cell_count;
#pragma omp parallel for num_threads(threads_) schedule(static) if (parallel_)
    for (int k = 0; k < n; ++k) {
      turn_[k] = placeCell(motion_[k], &model_.vertex_x[static_cast<size_t>(k) * kV],
                           &model_.vertex_y[static_cast<size_t>(k) * kV], model_.vertex_count[k],
                           &world_[static_cast<size_t>(k) * kV], &box_[4 * k]);
    }
  }

  void computeBondForces() {
    const int newly_broken =
        bond_pass_.run(motion_.data(), turn_.data(), bond_state_.data(), bond_load_.data(), threads_, parallel_);
    if (newly_broken > 0) {
      broken_count_ += newly_broken;
      rebuild_requested_ = true;  // the pair now needs a DEM contact
      const int bonds = static_cast<int>(bond_state_.size());
      for (int b = 0; b < bonds; ++b) {
        if (bond_state_[b] == kBondBreaking) just_broken_.push_back(b);
      }
    }
  }

  void computeContactForces() {
    const int pairs = static_cast<int>(contact_i_.size());
    int touching = 0;
#pragma omp parallel for num_threads(threads_) schedule(static) if (parallel_) reduction(+ : touching)
    for (int p = 0; p < pairs; ++p) {
      const int i = contact_i_[p], j = contact_j_[p];
      const double* bi = &box_[4 * i];
      const double* bj = &box_[4 * j];
      if (bi[1] <= bj[0] || bj[1] <= bi[0] || bi[3] <= bj[2] || bj[3] <= bi[2]) {
        contact_touching_[p] = 0;
        contact_reference_[p] = 0.0;
        continue;
      }
      // One slab above the other, with no reference overlap to follow: no force, whatever the
      // clip would give (contact.hpp).
      if (contactSkipsClip(motion_[i].z, motion_[j].z, model_.constants.contact.thickness, contact_reference_[p])) {
        contact_touching_[p] = 0;
        continue;
      }
      const Vec2* wi = &world_[static_cast<size_t>(i) * kV];
      const Vec2* wj = &world_[static_cast<size_t>(j) * kV];
      const int ni = model_.vertex_count[i], nj = model_.vertex_count[j];
      // Apart by more than the clip's rounding along the edge that kept them apart last time: the
      // clip would give no overlap, so the pair is apart (pair_separation.hpp).
      const double gap = model_.constants.separation_gap_fraction * (model_.radius[i] + model_.radius[j]);
      PolygonOverlap overlap;
      if (!clipUnlessApart(wi, ni, wj, nj, gap, contact_separating_edge_[p], overlap)) {
        contact_touching_[p] = 0;
        contact_reference_[p] = 0.0;
        continue;
      }
      const BodyState body_i = body(i), body_j = body(j);
      const PairForce f = demContactForce(overlap, body_i, body_j, model_.constants.contact, contact_reference_[p]);
      contact_load_[p] = contactLoad(f, body_i.centroid, body_j.centroid);
      contact_touching_[p] = f.touching ? 1 : 0;
      contact_reference_[p] = f.reference_area;
      touching += f.touching ? 1 : 0;
    }
    last_contacts_ = touching;
  }

  void stepOnce(double pusher_velocity, LoadSample& sum) {
    const ModelConstants& c = model_.constants;
    const int n = model_.cell_count;
    const double dt = c.time_step;
    updateWorldPolygons();
    computeBondForces();
    computeContactForces();
    bool blown = false, moved_far = false;
    const CellStepInputs in = {model_.mass.data(),
                               model_.inertia.data(),
                               model_.area.data(),
                               model_.inverse_mass.data(),
                               model_.inverse_inertia.data(),
                               model_.polar_moment.data(),
                               model_.vertex_count.data(),
                               model_.vertex_x.data(),
                               model_.vertex_y.data(),
                               world_.data(),
                               box_.data(),
                               bond_incidence_.offsets.data(),
                               bond_incidence_.entries.data(),
                               bond_state_.data(),
                               bond_load_.data(),
                               contact_incidence_.offsets.data(),
                               contact_incidence_.entries.data(),
                               contact_touching_.data(),
                               contact_load_.data()};
    // stepCell in two passes, as the CUDA backend runs it: every cell's first half, then the
    // structure sub-steps of the few cells that can reach the face, each pass's cells one by
    // one (a cell's step reads no other cell's motion, so the order changes no result). The
    // second pass hands its cells out one at a time, so that they do not all fall to the thread
    // whose static share holds the front of the sheet.
#pragma omp parallel for num_threads(threads_) schedule(static) if (parallel_) reduction(|| : blown, moved_far)
    for (int k = 0; k < n; ++k) {
      CellStepResult r;
      subcycled_[k] = beginCellStep(k, c, in, pusher_x_, pusher_velocity, motion_[k], structure_[k], r.pusher_fx,
                                    held_[k]);
      pusher_fx_[k] = r.pusher_fx;
      if (subcycled_[k]) continue;
      judgeCellStep(c, kRunawaySpeed, reference_[k], motion_[k], r);
      loaded_[k] = r.pusher_fx != 0.0 || structure_[k].panel_count > 0;
      blown = blown || r.blown;
      moved_far = moved_far || r.moved_far;
    }
    subcycled_cells_.clear();
    for (int k = 0; k < n; ++k) {
      if (subcycled_[k]) subcycled_cells_.push_back(k);
    }
    const int subcycled = static_cast<int>(subcycled_cells_.size());
#pragma omp parallel for num_threads(threads_) schedule(dynamic, 1) if (parallel_ && subcycled > 1) \
    reduction(|| : blown, moved_far)
    for (int i = 0; i < subcycled; ++i) {
      const int k = subcycled_cells_[i];
      subcycleStructureContact(k, c, in, &world_[static_cast<size_t>(k) * kV], held_[k], motion_[k], structure_[k]);
      CellStepResult r;
      judgeCellStep(c, kRunawaySpeed, reference_[k], motion_[k], r);
      loaded_[k] = pusher_fx_[k] != 0.0 || structure_[k].panel_count > 0;
      blown = blown || r.blown;
      moved_far = moved_far || r.moved_far;
    }
    if (moved_far || steps_since_rebuild_ + 1 >= c.max_steps_between_rebuilds) rebuild_requested_ = true;
    // Bonds broken in this step have applied their last force: they stop here.
    for (int b : just_broken_) bond_state_[b] = kBondBroken;
    just_broken_.clear();
    // Loads, summed in cell order (deterministic). Only the few cells at the pusher or the face
    // add anything (adding zero changes no sum); a byte per cell says which, so this serial loop
    // does not read every cell's 200-byte StructureContact.
    for (int k = 0; k < n; ++k) {
      if (!loaded_[k]) continue;
      sum.pusher_force += pusher_fx_[k];
      const StructureContact& s = structure_[k];
      for (int slot = 0; slot < s.panel_count; ++slot) {
        const SlotLoad l = structureSlotLoad(c, s, slot);
        sum.panel_horizontal[l.panel] += l.fx;
        sum.panel_lateral[l.panel] += l.fy;
        sum.panel_vertical[l.panel] += l.fz;
        sum.horizontal_raw += l.fx;
        sum.lateral_raw += l.fy;
        sum.vertical_raw += l.fz;
        sum.torque.x += l.tx; sum.torque.y += l.ty; sum.torque.z += l.tz;
        sum.panel_torque[l.panel].x += l.panel_tx;
        sum.panel_torque[l.panel].y += l.panel_ty;
        sum.panel_torque[l.panel].z += l.panel_tz;
      }
    }
    pusher_x_ += pusher_velocity * dt;
    time_ += dt;
    ++steps_;
    ++steps_since_rebuild_;
    if (blown) {
      std::ostringstream msg;
      msg << "numerical blow-up at t = " << time_ << " s: a cell state became non-finite or faster than "
          << kRunawaySpeed << " m/s (time step " << dt << " s)";
      health_error_ = msg.str();
    }
  }

  const Model& model_;
  const int threads_;
  const bool parallel_;  ///< run the loops on threads_ threads (false: one thread)
  const CpuBondPass bond_pass_;
  std::vector<CellMotion> motion_, reference_;
  std::vector<Vec2> world_;               ///< (cells x kV) world vertices [m]
  std::vector<Vec2> turn_;                ///< (cells) (cos yaw, sin yaw)
  std::vector<int> just_broken_;          ///< bonds broken in the current step
  std::vector<double> box_;               ///< (cells x 4) x0 x1 y0 y1 [m]
  std::vector<StructureContact> structure_;
  std::vector<double> pusher_fx_;         ///< (cells) [N]
  std::vector<unsigned char> loaded_;     ///< (cells) 1: the pusher or the structure acts on it this step
  std::vector<unsigned char> subcycled_;  ///< (cells) 1: it takes the structure sub-steps this step
  std::vector<HeldForces> held_;          ///< (cells) what its sub-steps hold, where subcycled_
  std::vector<int> subcycled_cells_;      ///< the cells with subcycled_ set, in cell order
  std::vector<unsigned char> bond_state_;  ///< (bonds) BondState
  std::vector<PairLoad> bond_load_;
  Incidence bond_incidence_, contact_incidence_;
  FixedRadiusNeighbourSearch search_;
  std::vector<int> contact_i_, contact_j_;  ///< sorted by (i, j)
  std::vector<double> contact_reference_;   ///< S_ref of each pair [m^2] (contact.hpp), -1: new
  std::vector<int> contact_separating_edge_;  ///< an edge that kept the pair apart (pair_separation.hpp)
  std::vector<int> previous_i_, previous_j_;
  std::vector<double> previous_reference_;
  std::vector<int> previous_separating_edge_;
  std::vector<KeptPairs> kept_ranges_;     ///< (threads) the pairs each range of candidates kept
  std::vector<unsigned char> contact_touching_;  ///< (pairs) S > 0 in this step
  std::vector<PairLoad> contact_load_;
  int broken_count_ = 0;
  int last_contacts_ = 0;
  long steps_since_rebuild_ = 0;
  bool rebuild_requested_ = true;
  double time_ = 0.0;
  long steps_ = 0;
  double pusher_x_ = 0.0;
  LoadSample loads_;
  std::string health_error_;
};

}  // namespace

std::unique_ptr<Backend> makeCpuBackend(const Model& model, int threads) {
  return std::make_unique<CpuBackend>(model, threads);
}

}  // namespace thin_ice
