// The contact list of the CUDA backend and its rebuild on the device (Algorithm 1's contact
// update; the CPU's rebuildContacts() in src/core/cpu_backend.cpp). Cells are hashed to bins of
// the search radius and sorted by bin with cub; each cell counts and then writes its candidate
// neighbours j > i sorted by j, so the list is sorted by (i, j) as on the CPU; a pair keeps the
// reference overlap S_ref it had in the old list (binary search), a new one gets -1; and the
// per-cell incidence lists are built and sorted into pair order, so that the gather sums in the
// CPU's order. Only the pair count comes back to the host. Include only from .cu files.
#pragma once

#include <cuda_runtime.h>

#include <vector>

#include "device_array.cuh"
#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/integrate.hpp"

namespace thin_ice {
namespace cuda {

/// What a rebuild reads (device pointers).
struct CandidateInputs {
  int cells;
  const CellMotion* motion;
  const double* radius;              ///< bounding radius of each cell [m]
  double search_radius;              ///< [m]
  double margin;                     ///< [m]
  const int* bond_offsets;           ///< per-cell bond incidence
  const int* bond_entries;
  const int* bond_i;
  const int* bond_j;
  const unsigned char* bond_broken;
};

class DeviceContactList {
 public:
  explicit DeviceContactList(int cells);

  /// Replaces the list by the candidate pairs of the present state. Returns true when the
  /// buffers below moved (a captured graph holding them must be captured again).
  bool rebuild(const CandidateInputs& in, cudaStream_t stream);
  /// Empties the list (reset).
  void clear() { count_ = 0; }
  /// Makes (i, j, S_ref) the list the next rebuild carries S_ref from (a restored checkpoint);
  /// the step must not read it before that rebuild (its incidence lists are stale). Returns true
  /// when the buffers moved.
  bool seed(const std::vector<int>& i, const std::vector<int>& j, const std::vector<double>& reference);
  /// The pairs and their S_ref, as the host sees them (a checkpoint).
  void download(std::vector<int>& i, std::vector<int>& j, std::vector<double>& reference) const;

  int count() const { return count_; }
  /// Pairs of the list that hold a separating edge (a diagnostic: copies the edges to the host).
  long pairsKeptApart() const;
  int capacity() const { return static_cast<int>(pair_i_.size()); }
  const int* pairI() const { return pair_i_.get(); }
  const int* pairJ() const { return pair_j_.get(); }
  double* referenceArea() const { return reference_area_.get(); }
  /// Per pair, an edge that kept it apart (pair_separation.hpp), carried like S_ref; not saved.
  int* separatingEdge() const { return separating_edge_.get(); }
  unsigned char* touching() const { return touching_.get(); }
  PairLoad* load() const { return load_.get(); }
  const int* incidenceOffsets() const { return offsets_.get(); }
  const int* incidenceEntries() const { return entries_.get(); }

 private:
  /// Room for `pairs` in the buffers the step reads; returns true when they moved.
  bool reserve(size_t pairs);

  const int cells_;
  int count_ = 0;
  unsigned int table_size_ = 1;  ///< bins of the spatial hash, a power of two >= 2 x cells
  // The list the step reads (capacity-sized).
  DeviceArray<int> pair_i_, pair_j_, offsets_, entries_, separating_edge_;
  DeviceArray<double> reference_area_;
  DeviceArray<unsigned char> touching_;
  DeviceArray<PairLoad> load_;
  // The rebuild's scratch.
  DeviceArray<int> new_i_, new_j_, new_separating_edge_, count_per_cell_, candidate_offsets_, cursor_, cell_ids_, sorted_cells_;
  DeviceArray<int> bin_start_, bin_end_;
  DeviceArray<double> new_reference_;
  DeviceArray<unsigned int> keys_, sorted_keys_;
  DeviceArray<unsigned char> temp_;
};

}  // namespace cuda
}  // namespace thin_ice
