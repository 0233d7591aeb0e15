// Checkpoint file layout (native endian; the byte-order mark refuses a file from a machine of
// the other order):
//   "TICKPT02" | u32 byte-order mark 0x01020304 | u32 hash length, hash bytes |
//   f64 pusher velocity | f64 time | i64 steps | f64 pusher x |
//   u64 cells,  CellMotion x cells (8 f64 each) | u64 bonds, u8 x bonds |
//   u64 pairs,  i32 i x pairs, i32 j x pairs, f64 S_ref x pairs |
//   u64 checksum: FNV-1a 64 of every byte before it | "TICKEND\0"
// Format 1 ("TICKPT01", the first) is the same without the checksum; it is still read.
#include "thin_ice_sim/checkpoint.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "thin_ice_sim/fnv_hash.hpp"
#include "thin_ice_sim/sheet_io.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {
namespace {

constexpr char kMagic[8] = {'T', 'I', 'C', 'K', 'P', 'T', '0', '2'};
constexpr char kMagicWithoutChecksum[8] = {'T', 'I', 'C', 'K', 'P', 'T', '0', '1'};
constexpr char kEnd[8] = {'T', 'I', 'C', 'K', 'E', 'N', 'D', '\0'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  template <typename T>
  void putArray(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    if (!values.empty()) bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void putRaw(const char* data, size_t size) { bytes_.append(data, size); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(std::string bytes, std::string path) : bytes_(std::move(bytes)), path_(std::move(path)) {}
  template <typename T>
  T get(const char* what) {
    T value;
    take(&value, sizeof(T), what);
    return value;
  }
  /// `count` elements, refused before allocating when the file cannot hold them.
  template <typename T>
  std::vector<T> getArray(std::uint64_t count, const char* what) {
    if (count > (bytes_.size() - cursor_) / sizeof(T)) fail(std::string("truncated in ") + what);
    std::vector<T> values(static_cast<size_t>(count));
    if (count > 0) take(values.data(), values.size() * sizeof(T), what);
    return values;
  }
  void expect(const char (&tag)[8], const char* what) {
    char found[8];
    take(found, sizeof(found), what);
    if (std::memcmp(found, tag, sizeof(found)) != 0) fail(std::string("no ") + what);
  }
  /// Which of two 8-byte tags comes next: 0 for `a`, 1 for `b`; fails naming `what` otherwise.
  int expectOneOf(const char (&a)[8], const char (&b)[8], const char* what) {
    char found[8];
    take(found, sizeof(found), what);
    if (std::memcmp(found, a, sizeof(found)) == 0) return 0;
    if (std::memcmp(found, b, sizeof(found)) == 0) return 1;
    fail(std::string("no ") + what);
  }
  /// FNV-1a of every byte read so far.
  std::uint64_t checksumSoFar() const { return fnv1a64(bytes_.data(), cursor_); }
  void expectEnd() {
    if (cursor_ != bytes_.size()) fail(std::to_string(bytes_.size() - cursor_) + " bytes after the end mark");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("checkpoint '" + path_ + "': " + what);
  }

 private:
  void take(void* out, size_t size, const char* what) {
    if (size > bytes_.size() - cursor_) fail(std::string("truncated in ") + what);
    std::memcpy(out, bytes_.data() + cursor_, size);
    cursor_ += size;
  }
  std::string bytes_;
  std::string path_;
  size_t cursor_ = 0;
};

}  // namespace

Checkpoint takeCheckpoint(const Simulation& sim) {
  return {sim.scenario().hash, sim.pusherVelocity(), sim.saveState()};
}

void restoreCheckpoint(Simulation& sim, const Checkpoint& checkpoint, bool accept_changed_scenario) {
  if (!accept_changed_scenario && checkpoint.scenario_hash != sim.scenario().hash) {
    throw std::invalid_argument("checkpoint is of scenario hash " + checkpoint.scenario_hash + ", this run's is " +
                                sim.scenario().hash + " (the scenario file or its overrides changed)");
  }
  if (!std::isfinite(checkpoint.pusher_velocity)) {
    throw std::invalid_argument("checkpoint's pusher velocity is " + std::to_string(checkpoint.pusher_velocity) +
                                " m/s; allowed: finite");
  }
  sim.restoreState(checkpoint.state);
  sim.setPusherVelocity(checkpoint.pusher_velocity);
}

void writeCheckpoint(const std::string& path, const Checkpoint& c) {
  const BackendState& s = c.state;
  Writer w;
  w.putRaw(kMagic, sizeof(kMagic));
  w.put(kByteOrderMark);
  w.put(static_cast<std::uint32_t>(c.scenario_hash.size()));
  w.putRaw(c.scenario_hash.data(), c.scenario_hash.size());
  w.put(c.pusher_velocity);
  w.put(s.time);
  w.put(static_cast<std::int64_t>(s.steps));
  w.put(s.pusher_x);
  w.put(static_cast<std::uint64_t>(s.motion.size()));
  w.putArray(s.motion);
  w.put(static_cast<std::uint64_t>(s.bond_state.size()));
  w.putArray(s.bond_state);
  w.put(static_cast<std::uint64_t>(s.contact_i.size()));
  w.putArray(s.contact_i);
  w.putArray(s.contact_j);
  w.putArray(s.contact_reference);
  w.put(fnv1a64(w.bytes().data(), w.bytes().size()));
  w.putRaw(kEnd, sizeof(kEnd));
  writeFileAtomically(path, w.bytes());
}

Checkpoint readCheckpoint(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("checkpoint '" + path + "': cannot be read");
  Reader r(std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()), path);
  const bool checksummed =
      r.expectOneOf(kMagic, kMagicWithoutChecksum, "checkpoint header (TICKPT02 or TICKPT01: another file or "
                                                   "another format version)") == 0;
  if (r.get<std::uint32_t>("byte-order mark") != kByteOrderMark) r.fail("written on a machine of the other byte order");
  Checkpoint c;
  c.checksummed = checksummed;
  const std::uint32_t hash_length = r.get<std::uint32_t>("scenario hash");
  const std::vector<char> hash = r.getArray<char>(hash_length, "scenario hash");
  c.scenario_hash.assign(hash.begin(), hash.end());
  c.pusher_velocity = r.get<double>("pusher velocity");
  BackendState& s = c.state;
  s.time = r.get<double>("time");
  s.steps = static_cast<long>(r.get<std::int64_t>("step count"));
  s.pusher_x = r.get<double>("pusher position");
  s.motion = r.getArray<CellMotion>(r.get<std::uint64_t>("cell count"), "cells");
  s.bond_state = r.getArray<unsigned char>(r.get<std::uint64_t>("bond count"), "bonds");
  const std::uint64_t pairs = r.get<std::uint64_t>("pair count");
  s.contact_i = r.getArray<int>(pairs, "pairs");
  s.contact_j = r.getArray<int>(pairs, "pairs");
  s.contact_reference = r.getArray<double>(pairs, "pairs");
  if (checksummed) {
    const std::uint64_t computed = r.checksumSoFar();
    if (r.get<std::uint64_t>("checksum") != computed) {
      r.fail("the checksum does not match the contents: the file is damaged (refused; nothing was resumed)");
    }
  }
  r.expect(kEnd, "end mark (truncated or corrupt)");
  r.expectEnd();
  return c;
}

}  // namespace thin_ice
