// 64-bit FNV-1a, the project's one hash of bytes: the scenario hash (file text and overrides) and
// the checkpoint's checksum. Not cryptographic: it finds a changed or damaged file, not a forged one.
#pragma once

#include <cstddef>
#include <cstdint>

namespace thin_ice {

constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ULL;

/// FNV-1a of `size` bytes at `data`, continuing from `hash` (kFnvOffsetBasis to start).
inline std::uint64_t fnv1a64(const char* data, std::size_t size, std::uint64_t hash = kFnvOffsetBasis) {
  for (std::size_t k = 0; k < size; ++k) {
    hash ^= static_cast<unsigned char>(data[k]);
    hash *= 1099511628211ULL;
  }
  return hash;
}

}  // namespace thin_ice
