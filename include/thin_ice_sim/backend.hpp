// The interface every backend (CPU with OpenMP, CUDA) implements behind Simulation:
// upload the model, step(n), download cells, read loads.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "thin_ice_sim/load_sample.hpp"
#include "thin_ice_sim/model.hpp"

namespace thin_ice {

/// What a backend needs to go on where a run stopped (a checkpoint): the cells' motion, every
/// bond's life and the contact pairs with their reference overlaps S_ref (contact.hpp). Taken
/// between steps, where no bond is kBondBreaking any more (it applied its last force in the last
/// step taken), so a state moves between backends unchanged.
struct BackendState {
  double time = 0.0;                       ///< [s] simulated, as the backend summed it
  long steps = 0;
  double pusher_x = 0.0;                   ///< [m]
  std::vector<CellMotion> motion;          ///< (cells)
  std::vector<unsigned char> bond_state;   ///< (bonds) kBondIntact or kBondBroken
  std::vector<int> contact_i, contact_j;   ///< candidate pairs, sorted by (i, j)
  std::vector<double> contact_reference;   ///< S_ref of each pair [m^2], -1: new to the list
};
// Not saved: the positions at the last contact rebuild and the steps since it (Algorithm 1's
// rebuild test). A restored state is rebuilt at its first step instead; that cannot change the
// forces: a pair within reach of touching before the next rebuild is in any rebuild's list
// (the search margin covers two cells each moving and turning as far as a rebuild allows,
// model.cpp), a pair that stays keeps its S_ref,
// and a pair that leaves held S_ref = 0 (not touching), which is what a new pair gets on its
// first step without contact. test_checkpoint checks the result bit for bit.

/// Bonds in any state but kBondIntact: the broken-bond count a restored backend starts from.
inline int countBrokenBonds(const std::vector<unsigned char>& bond_state) {
  int broken = 0;
  for (const unsigned char b : bond_state) broken += b != kBondIntact ? 1 : 0;
  return broken;
}

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  /// Back to the model's initial state, t = 0.
  virtual void reset() = 0;
  /// Takes `steps` time steps with the pusher at `pusher_velocity` [m/s]. Loads are averaged
  /// over these steps. Stops early and sets healthError() on a numerical blow-up.
  virtual void step(long steps, double pusher_velocity) = 0;
  virtual double time() const = 0;
  virtual long stepCount() const = 0;
  virtual double pusherPosition() const = 0;
  virtual LoadSample loads() const = 0;
  virtual std::vector<CellSnapshot> cells() const = 0;
  /// Empty while healthy; else what went wrong (non-finite state, runaway speed).
  virtual std::string healthError() const = 0;
  /// The state between steps, for a checkpoint.
  virtual BackendState saveState() const = 0;
  /// Continues from `state` (sizes checked by the caller against the model). The next step
  /// rebuilds the contact list and carries S_ref over from the pairs of `state`, as any rebuild
  /// does; loads() is empty until then.
  virtual void restoreState(const BackendState& state) = 0;
  /// Contact pairs that hold a remembered separating edge now: the next step skips their polygon
  /// clip while that edge still keeps them apart (physics/pair_separation.hpp). A diagnostic, for
  /// the test that checks edges are found and kept (not that a kept edge is read, nor that it is
  /// carried through a rebuild: bit-identity with every pair clipped covers those).
  virtual long pairsKeptApart() const = 0;
};

/// Cell snapshots from a backend's state: cell k is in the intact sheet while any of its bonds
/// holds (bond_broken: one BondState per bond of the model; any but kBondIntact is broken).
std::vector<CellSnapshot> makeCellSnapshots(const Model& model, const std::vector<CellMotion>& motion,
                                            const std::vector<unsigned char>& bond_broken);

/// For each of `cell_count` cells, the number of cells in its piece: the connected component of
/// the graph whose edges are the intact bonds (bond b joins bond_i[b] and bond_j[b]; bond_broken[b]
/// other than kBondIntact removes it). A free block has 1.
std::vector<int> bondedPieceSizes(int cell_count, const std::vector<int>& bond_i, const std::vector<int>& bond_j,
                                  const std::vector<unsigned char>& bond_broken);

/// How Simulation reaches the GPU backend without the core depending on CUDA: a build with the
/// CUDA library registers this provider (thin_ice_sim/built_backends.hpp); without it there is none.
struct GpuBackendProvider {
  /// Empty when a usable device is present, else why not (no device, driver too old...).
  std::string (*unavailable_reason)();
  /// One line naming the device ("NVIDIA H100 80GB HBM3, compute capability 9.0").
  std::string (*device_description)();
  std::unique_ptr<Backend> (*make)(const Model& model);
  /// Bytes in use on the device (total minus free, all processes): benchmarks take the growth
  /// across building and stepping a backend as its memory.
  double (*device_memory_in_use)();
};

void setGpuBackendProvider(const GpuBackendProvider* provider);
const GpuBackendProvider* gpuBackendProvider();

}  // namespace thin_ice
