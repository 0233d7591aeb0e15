// Seeded random mutation of the two files a run reads (issue #33): the scenario loader and the
// checkpoint reader get thousands of damaged copies of a good file (bytes flipped, cut, repeated,
// numbers replaced by huge, tiny, negative or non-finite ones) and must either accept the file or
// refuse it with the error of their interface (ScenarioError, std::runtime_error) whose message is
// one line of printable text; nothing else may escape, and nothing may crash. The seed and the
// count come from the environment (THIN_ICE_FUZZ_SEED, THIN_ICE_FUZZ_CASES) so that a longer
// search runs from the same test; CI runs the default, a few seconds.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/checkpoint.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {
namespace {

const std::string kQuick = std::string(THIN_ICE_SOURCE_DIR) + "/config/scenarios/quick.yaml";

long environmentNumber(const char* name, long fallback) {
  const char* text = std::getenv(name);
  return text != nullptr ? std::strtol(text, nullptr, 10) : fallback;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// One random damage of `good`: a flipped bit, a cut, a repeated or deleted span, a random byte
/// run, or (text) a number replaced by one of the values that broke runs before.
std::string mutate(const std::string& good, std::mt19937_64& random, bool text) {
  std::string s = good;
  std::uniform_int_distribution<size_t> at(0, s.empty() ? 0 : s.size() - 1);
  switch (random() % 6) {
    case 0: s[at(random)] ^= static_cast<char>(1u << (random() % 8)); break;
    case 1: s.resize(at(random)); break;
    case 2: {
      const size_t a = at(random), n = std::min<size_t>(s.size() - a, random() % 64);
      s.insert(a, s.substr(a, n));
      break;
    }
    case 3: {
      const size_t a = at(random);
      s.erase(a, std::min<size_t>(s.size() - a, random() % 64));
      break;
    }
    case 4:
      for (int k = 0; k < 8; ++k) s[at(random)] = static_cast<char>(random() % 256);
      break;
    default:
      if (text) {
        static const char* kValues[] = {"1e300", "-1e300", "1e-300", "0", "-0", "nan", ".inf", "-.inf", "1e15",
                                        "-1", "2147483648", "999999999999999999999", "0x10", "~", "[]", "{}"};
        // Replace the digits after a ': ' by one of the values.
        const size_t colon = s.find(": ", at(random));
        if (colon != std::string::npos) {
          const size_t start = colon + 2, end = s.find_first_of(" #\n", start);
          s.replace(start, (end == std::string::npos ? s.size() : end) - start, kValues[random() % 16]);
        }
      } else {
        s[at(random)] = static_cast<char>(0xff);
      }
  }
  return s;
}

/// The message of an accepted refusal: one line of printable ASCII, not empty.
void expectOneReadableLine(const std::string& message, const std::string& what) {
  EXPECT_FALSE(message.empty()) << what;
  for (const char c : message) {
    const unsigned char u = static_cast<unsigned char>(c);
    ASSERT_TRUE(u >= 0x20 && u < 0x7f) << what << ": a byte " << static_cast<int>(u) << " in: " << message;
  }
}

TEST(InputFuzz, TheScenarioLoaderAcceptsOrRefusesInOneLine) {
  const long seed = environmentNumber("THIN_ICE_FUZZ_SEED", 20261204), cases = environmentNumber("THIN_ICE_FUZZ_CASES", 1500);
  std::mt19937_64 random(static_cast<std::uint64_t>(seed));
  const std::string good = readBytes(kQuick);
  ASSERT_FALSE(good.empty());
  const std::string path = ::testing::TempDir() + "fuzz_scenario.yaml";
  long accepted = 0, refused = 0;
  for (long k = 0; k < cases; ++k) {
    std::string damaged = mutate(good, random, true);
    if (random() % 4 == 0) damaged = mutate(damaged, random, true);  // sometimes two at once
    writeBytes(path, damaged);
    try {
      loadScenario(path);
      ++accepted;
    } catch (const ScenarioError& e) {
      ++refused;
      expectOneReadableLine(e.what(), "case " + std::to_string(k));
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << k << " (seed " << seed << "): not a ScenarioError: " << e.what();
    }
  }
  std::remove(path.c_str());
  EXPECT_GT(refused, cases / 10) << "the mutations should break most files";
  std::printf("scenario fuzz: seed %ld, %ld cases, %ld accepted, %ld refused\n", seed, cases, accepted, refused);
}

TEST(InputFuzz, TheCheckpointReaderRefusesEveryDamagedFile) {
  // Every mutation that changes the bytes is refused: format 2 carries a checksum of its contents.
  const long seed = environmentNumber("THIN_ICE_FUZZ_SEED", 20261204), cases = environmentNumber("THIN_ICE_FUZZ_CASES", 1500);
  std::mt19937_64 random(static_cast<std::uint64_t>(seed) + 1);
  Simulation sim(loadScenario(kQuick, {"sheet.length=0.6", "structure.toe_x=0.7", "bottom.distance_from_structure=0.3"}),
                 BackendKind::kCpu);
  sim.advance(0.01);
  const std::string path = ::testing::TempDir() + "fuzz_checkpoint.bin";
  writeCheckpoint(path, takeCheckpoint(sim));
  const std::string good = readBytes(path);
  long refused = 0;
  for (long k = 0; k < cases; ++k) {
    const std::string damaged = mutate(good, random, false);
    if (damaged == good) continue;
    writeBytes(path, damaged);
    try {
      readCheckpoint(path);
      ADD_FAILURE() << "case " << k << " (seed " << seed << "): a damaged checkpoint was read";
    } catch (const std::runtime_error& e) {
      ++refused;
      expectOneReadableLine(e.what(), "case " + std::to_string(k));
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << k << ": not a runtime_error: " << e.what();
    }
  }
  std::remove(path.c_str());
  std::printf("checkpoint fuzz: seed %ld, %ld damaged files refused\n", seed, refused);
}

}  // namespace
}  // namespace thin_ice
