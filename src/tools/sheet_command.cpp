// `thin_ice sheet`: generates a Voronoi ice sheet from a YAML file, writes its picture and polygon
// list, and prints its statistics.
//   thin_ice sheet --config config/sheet_demo.yaml --out DIR [--seed N]
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <sys/stat.h>

#include "commands.hpp"
#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/sheet_io.hpp"

namespace {

const char* kUsage = "usage: thin_ice sheet --config FILE --out DIR [--seed N]\n";

struct DemoConfig {
  thin_ice::IceSheetSpec sheet;
  double thickness = 0.05;  // [m] ice thickness h, for the A/h^2 check
};

double readNumber(const YAML::Node& node, const std::string& file, const std::string& key) {
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw std::invalid_argument(file + ": " + key + " = '" + YAML::Dump(node) +
                                "' is not a number");
  }
}

DemoConfig loadConfig(const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(file + ": cannot read YAML: " + e.what());
  }
  DemoConfig c;
  const std::set<std::string> known = {"length",   "width",  "x_min",           "cell_size",
                                       "layout",   "jitter", "lloyd_iterations", "seed",
                                       "thickness"};
  if (!root.IsMap()) throw std::invalid_argument(file + ": expected a map of sheet parameters");
  for (const auto& kv : root) {
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) {
      throw std::invalid_argument(file + ": unknown key '" + key +
                                  "'; allowed: length width x_min cell_size layout jitter "
                                  "lloyd_iterations seed thickness");
    }
    const YAML::Node& v = kv.second;
    if (key == "length") c.sheet.length = readNumber(v, file, key);
    if (key == "width") c.sheet.width = readNumber(v, file, key);
    if (key == "x_min") c.sheet.x_min = readNumber(v, file, key);
    if (key == "cell_size") c.sheet.cell_size = readNumber(v, file, key);
    if (key == "jitter") c.sheet.jitter = readNumber(v, file, key);
    if (key == "thickness") c.thickness = readNumber(v, file, key);
    if (key == "lloyd_iterations") c.sheet.lloyd_iterations = static_cast<int>(readNumber(v, file, key));
    if (key == "seed") c.sheet.seed = static_cast<std::uint64_t>(readNumber(v, file, key));
    if (key == "layout") c.sheet.layout = thin_ice::parseSeedLayout(v.as<std::string>(), file + ": layout");
  }
  if (!(c.thickness > 0.0)) {
    throw std::invalid_argument(file + ": thickness = " + std::to_string(c.thickness) +
                                " is invalid; allowed: > 0 m");
  }
  return c;
}

}  // namespace

int thin_ice::cli::sheetCommand(int argc, char** argv) {
  std::string config_path, out_dir;
  long long seed_override = -1;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--help" || arg == "-h") {  // as every other command: its usage on stdout
      std::cout << kUsage;
      return 0;
    }
    if ((arg == "--config" || arg == "--out" || arg == "--seed") && k + 1 < argc) {
      const std::string value = argv[++k];
      if (arg == "--config") config_path = value;
      if (arg == "--out") out_dir = value;
      if (arg == "--seed") {
        // Decimal digits only, as the scenario's sheet.seed: "abc", "-1" or "1e3" is refused here.
        const bool digits = !value.empty() && value.size() <= 18 &&
                            value.find_first_not_of("0123456789") == std::string::npos;
        if (!digits) {
          std::cerr << "thin_ice sheet: --seed '" << value << "'; allowed: a whole number 0 to 10^18 - 1\n";
          return 2;
        }
        seed_override = std::stoll(value);
      }
    } else {
      std::cerr << kUsage;
      return 2;
    }
  }
  if (config_path.empty() || out_dir.empty()) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    DemoConfig config = loadConfig(config_path);
    if (seed_override >= 0) config.sheet.seed = static_cast<std::uint64_t>(seed_override);
    const auto t0 = std::chrono::steady_clock::now();
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(config.sheet);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ::mkdir(out_dir.c_str(), 0755);
    thin_ice::writeSheetSvg(sheet, out_dir + "/sheet.svg");
    thin_ice::writeCellPolygons(sheet, out_dir + "/cells.txt");
    const thin_ice::IceSheetStats s = thin_ice::computeStats(sheet);
    const double h = config.thickness;
    std::printf("ice sheet %.3g m x %.3g m, layout %s, seed %llu, %d Lloyd iterations\n",
                config.sheet.length, config.sheet.width, thin_ice::toString(config.sheet.layout).c_str(),
                static_cast<unsigned long long>(config.sheet.seed), config.sheet.lloyd_iterations);
    std::printf("  cells                 %d\n", s.cell_count);
    std::printf("  shared edges (bonds)  %d (%.2f per cell)\n", s.edge_count, s.mean_neighbours);
    std::printf("  sheet area            %.9g m^2 (rectangle %.9g m^2)\n", s.total_area,
                config.sheet.length * config.sheet.width);
    std::printf("  mean cell size        %.4g m (target %.4g m)\n", s.mean_cell_size, config.sheet.cell_size);
    std::printf("  cell area min/mean/max %.4g / %.4g / %.4g m^2\n", s.min_cell_area, s.mean_cell_area,
                s.max_cell_area);
    std::printf("  A/h^2 min/mean        %.1f / %.1f (h = %.3g m; the model needs > 10)\n",
                s.min_cell_area / (h * h), s.mean_cell_area / (h * h), h);
    std::printf("  vertices per cell     %d .. %d\n", s.min_vertices, s.max_vertices);
    std::printf("  mean bond edge l-bar  %.4g m\n", s.mean_edge_length);
    std::printf("  generated in          %.3f s\n", seconds);
    std::printf("wrote %s/sheet.svg and %s/cells.txt\n", out_dir.c_str(), out_dir.c_str());
  } catch (const std::exception& e) {
    std::cerr << "thin_ice sheet: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
