// What the scenario tests share (test_scenario.cpp, test_scenario_rules.cpp): the shipped
// scenarios' folder, edits of a YAML text by key, and a fixture with its own directory that writes
// files, loads them and checks the one-line message of a refusal.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {
namespace scenario_test {

namespace fs = std::filesystem;

inline const std::string kSourceDir = THIN_ICE_SOURCE_DIR;
inline const std::string kScenarioDir = kSourceDir + "/config/scenarios/";

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// `yaml` with the line of `section.key` replaced by `new_line` ("" removes it). The key's line
/// is the first "  key:" after the line "section:" and before the next section.
inline std::string withLine(const std::string& yaml, const std::string& section, const std::string& key,
                     const std::string& new_line) {
  std::vector<std::string> lines = splitLines(yaml);
  bool in_section = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (!line.empty() && line[0] != ' ' && line[0] != '#') in_section = line == section + ":";
    if (in_section && line.rfind("  " + key + ":", 0) == 0) {
      if (new_line.empty()) {
        lines.erase(lines.begin() + static_cast<long>(i));
      } else {
        lines[i] = new_line;
      }
      std::string out;
      for (const std::string& l : lines) out += l + "\n";
      return out;
    }
  }
  throw std::logic_error("test setup: no " + section + "." + key + " in the YAML text");
}

/// `yaml` with `section.key` set to `value` (its comment dropped).
inline std::string withValue(const std::string& yaml, const std::string& section, const std::string& key,
                      const std::string& value) {
  return withLine(yaml, section, key, "  " + key + ": " + value);
}

/// Each test gets its own directory for the YAML files it writes.
class ScenarioFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("thin_ice_scenario_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    quick_ = readText(kScenarioDir + "quick.yaml");
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// The message of the ScenarioError that loading `path` throws ("" and a failure when none).
  static std::string errorOf(const std::string& path,
                             const std::vector<std::string>& overrides = {}) {
    try {
      loadScenario(path, overrides);
    } catch (const ScenarioError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no ScenarioError for " << path;
    return "";
  }

  /// Writes `text` as `name`, loads it, and checks the one-line message mentions every part.
  void expectError(const std::string& name, const std::string& text,
                   std::initializer_list<std::string> parts,
                   const std::vector<std::string>& overrides = {}) const {
    const std::string message = errorOf(write(name, text), overrides);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(name), std::string::npos) << "file name missing: " << message;
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing: " << message;
    }
  }

  fs::path dir_;
  std::string quick_;
};

}  // namespace scenario_test
}  // namespace thin_ice
