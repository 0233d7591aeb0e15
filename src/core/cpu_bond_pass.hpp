// The CPU backend's bond pass: RMIB bond forces and failure (paper Eqs. 8-13, the one definition
// in include/thin_ice_sim/physics/bond.hpp) for every bond, in a form the compiler vectorises.
//
// Why a separate pass: with the bond records as an array of 112-byte structures and the law's
// branches on a run-time constant (the smoothing exponent), the compiler
// keeps the loop scalar, about 190 instructions a bond (docs/performance.md). Here the records
// are held column by column (one array per field), the bonds are taken in blocks of kBondBlock,
// and for the three exponents of Table 1 (n = 1, 2, 1/2, the same for K_n and K_v) the law is
// compiled with the exponent fixed, so that its branches fold
// or become selects and the compiler computes four bonds per AVX2 instruction. Other exponents
// take the same law on the same columns, scalar.
//
// Every bond of a block that holds an intact bond is computed, the broken ones too (their loads
// are written and never read: the per-cell gather skips broken bonds); blocks with none are
// skipped. Blocks are fixed by bond index, so a bond is computed by the same instructions on any
// number of threads and the run stays bit-identical across thread counts.
#pragma once

#include <vector>

#include "thin_ice_sim/model.hpp"

namespace thin_ice {

/// Bonds per block: a multiple of every vector width in use (4 and 8 doubles).
constexpr int kBondBlock = 64;

/// BondRest, one array per field, bond b at index b.
struct BondRestColumns {
  std::vector<double> anchor_i_x, anchor_i_y, anchor_j_x, anchor_j_y, normal_x, normal_y;
  std::vector<double> edge_length, distance, k_normal, k_shear, k_vertical;
  std::vector<double> damping_normal, damping_shear, damping_vertical;
};

class CpuBondPass {
 public:
  explicit CpuBondPass(const Model& model);

  /// Computes the load of every intact bond into load[b] and marks the bonds that fail in this
  /// step kBondBreaking in state; returns how many did. motion and turn: (cells) the cells'
  /// state and (cos, sin) of their yaw in this step.
  int run(const CellMotion* motion, const Vec2* turn, unsigned char* state, PairLoad* load, int threads,
          bool parallel) const;

  /// Whether the scenario's constants have a vectorised instance (else the scalar one runs).
  bool vectorised() const { return vectorised_; }

  /// Computes bonds [first, first + count) of the block into load and breaks (1: Eq. 13 met);
  /// returns non-zero when any of them breaks.
  using BlockKernel = long long (*)(const Model& model, const BondRestColumns& rest, int first, int count,
                                    const CellMotion* motion, const Vec2* turn, PairLoad* load,
                                    long long* breaks);

 private:
  const Model& model_;
  BondRestColumns rest_;
  BlockKernel kernel_;
  bool vectorised_;
};

}  // namespace thin_ice
