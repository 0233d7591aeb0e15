// The CPU backend's bond pass (see cpu_bond_pass.hpp). This file is compiled with
// -fno-trapping-math and -fno-rounding-math (CMakeLists.txt): without them the compiler may not
// compute both sides of the law's selects (a division or a square root "could trap") and so cannot
// vectorise the loop. Neither changes a computed value: the program reads no floating-point
// exception flag, and this code runs in the default rounding mode (only CGAL's mesh generation
// changes it, inside its own calls).
#include "cpu_bond_pass.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace thin_ice {
namespace {

/// Exponent codes of the kernels: 0 as the scenario gives (scalar), 1: n = 1, 2: n = 2, 3: n = 1/2.
constexpr double exponentOfCode(int code) { return code == 1 ? 1.0 : (code == 2 ? 2.0 : 0.5); }

template <int kExponentCode>
long long forceBlock(const Model& model, const BondRestColumns& r, int first, int count,
                     const CellMotion* __restrict motion, const Vec2* __restrict turn,
                     PairLoad* __restrict load, long long* __restrict breaks) {
  // A local copy, so that the values fixed here are known where the law reads them (they fold).
  BondConstants c = model.constants.bond;
  if (kExponentCode != 0) {
    c.exponent_h = c.exponent_v = exponentOfCode(kExponentCode);
  }
  const int* __restrict bond_i = model.bond_i.data();
  const int* __restrict bond_j = model.bond_j.data();
  const double* __restrict mass = model.mass.data();
  const double* __restrict inertia = model.inertia.data();
  long long any_breaks = 0;
  for (int t = 0; t < count; ++t) {
    const int b = first + t;
    const int i = bond_i[b], j = bond_j[b];
    const BondRest rest = {{{r.anchor_i_x[b], r.anchor_i_y[b]},
                            {r.anchor_j_x[b], r.anchor_j_y[b]},
                            {r.normal_x[b], r.normal_y[b]},
                            r.edge_length[b],
                            r.distance[b]},
                           r.k_normal[b],
                           r.k_shear[b],
                           r.k_vertical[b],
                           r.damping_normal[b],
                           r.damping_shear[b],
                           r.damping_vertical[b]};
    const BondForce f = rmibBondForce(rest, bodyOf(motion[i], mass[i], inertia[i]), turn[i],
                                      bodyOf(motion[j], mass[j], inertia[j]), turn[j], c);
    const PairLoad l = bondLoad(f);
    // Field by field: a whole-struct store keeps the compiler from vectorising.
    load[b].force_on_j.x = l.force_on_j.x;
    load[b].force_on_j.y = l.force_on_j.y;
    load[b].fz_on_j = l.fz_on_j;
    load[b].torque[0] = l.torque[0];
    load[b].torque[1] = l.torque[1];
    breaks[t] = f.breaks ? 1 : 0;
    any_breaks |= breaks[t];
  }
  return any_breaks;
}

/// The kernel for the scenario's exponents: one specialised for n = 1, 2 or 1/2 on both springs.
CpuBondPass::BlockKernel kernelFor(const BondConstants& c, bool& vectorised) {
  int code = 0;
  if (c.exponent_h == c.exponent_v) {
    code = c.exponent_h == 1.0 ? 1 : (c.exponent_h == 2.0 ? 2 : (c.exponent_h == 0.5 ? 3 : 0));
  }
  vectorised = code != 0;
  constexpr std::array<CpuBondPass::BlockKernel, 4> kernels = {&forceBlock<0>, &forceBlock<1>, &forceBlock<2>,
                                                               &forceBlock<3>};
  return kernels[code];
}

}  // namespace

CpuBondPass::CpuBondPass(const Model& model) : model_(model), kernel_(kernelFor(model.constants.bond, vectorised_)) {
  BondRestColumns& r = rest_;
  for (const BondRest& b : model.bond_rest) {
    r.anchor_i_x.push_back(b.anchor_i.x);
    r.anchor_i_y.push_back(b.anchor_i.y);
    r.anchor_j_x.push_back(b.anchor_j.x);
    r.anchor_j_y.push_back(b.anchor_j.y);
    r.normal_x.push_back(b.normal.x);
    r.normal_y.push_back(b.normal.y);
    r.edge_length.push_back(b.edge_length);
    r.distance.push_back(b.distance);
    r.k_normal.push_back(b.k_normal);
    r.k_shear.push_back(b.k_shear);
    r.k_vertical.push_back(b.k_vertical);
    r.damping_normal.push_back(b.damping_normal);
    r.damping_shear.push_back(b.damping_shear);
    r.damping_vertical.push_back(b.damping_vertical);
  }
}

int CpuBondPass::run(const CellMotion* motion, const Vec2* turn, unsigned char* state, PairLoad* load, int threads,
                     bool parallel) const {
  const int bonds = static_cast<int>(model_.bond_rest.size());
  const int blocks = (bonds + kBondBlock - 1) / kBondBlock;
  int newly_broken = 0;
#pragma omp parallel for num_threads(threads) schedule(static) if (parallel) reduction(+ : newly_broken)
  for (int block = 0; block < blocks; ++block) {
    const int first = block * kBondBlock, count = std::min(kBondBlock, bonds - first);
    if (std::memchr(state + first, kBondIntact, count) == nullptr) continue;  // all broken
    long long breaks[kBondBlock];
    if (kernel_(model_, rest_, first, count, motion, turn, load, breaks) == 0) continue;
    for (int t = 0; t < count; ++t) {
      if (breaks[t] != 0 && state[first + t] == kBondIntact) {
        state[first + t] = kBondBreaking;  // for good; its force of this step still acts
        ++newly_broken;
      }
    }
  }
  return newly_broken;
}

}  // namespace thin_ice
