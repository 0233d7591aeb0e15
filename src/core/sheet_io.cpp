#include "thin_ice_sim/sheet_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace thin_ice {

void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw std::runtime_error("cannot write '" + temporary + "': " + std::strerror(errno));
    }
    out << text;
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw std::runtime_error("write to '" + temporary + "' failed");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot rename '" + temporary + "' to '" + path + "': " + reason);
  }
}

void writeSheetSvg(const IceSheet& sheet, const std::string& path) {
  const IceSheetSpec& s = sheet.spec;
  // 1 m = pixels_per_metre px; the longer side is drawn about 1600 px wide.
  const double pixels_per_metre = 1600.0 / std::max(s.length, s.width);
  const double margin = 20.0;
  const double w = s.length * pixels_per_metre + 2 * margin;
  const double h = s.width * pixels_per_metre + 2 * margin;
  auto px = [&](Vec2 p) {
    return Vec2{margin + (p.x - s.x_min) * pixels_per_metre,
                margin + (0.5 * s.width - p.y) * pixels_per_metre};
  };
  std::ostringstream svg;
  svg << std::fixed << std::setprecision(2);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h << "'>\n";
  svg << "<rect width='100%' height='100%' fill='#0b3d5c'/>\n";
  static const char* kFills[] = {"#e8f1f8", "#d6e6f2", "#c4dbec", "#f2f7fb"};
  for (size_t i = 0; i < sheet.cells.size(); ++i) {
    const CellGeometry& c = sheet.cells[i];
    svg << "<polygon fill='" << kFills[i % 4] << "' stroke='#5b7c99' stroke-width='0.8' points='";
    for (const Vec2& v : c.vertices) {
      const Vec2 p = px(c.centroid + v);
      svg << p.x << ',' << p.y << ' ';
    }
    svg << "'/>\n";
  }
  for (const SharedEdge& e : sheet.edges) {
    const Vec2 a = px(sheet.cells[e.i].centroid), b = px(sheet.cells[e.j].centroid);
    svg << "<line x1='" << a.x << "' y1='" << a.y << "' x2='" << b.x << "' y2='" << b.y
        << "' stroke='#c0392b' stroke-width='0.5' stroke-opacity='0.6'/>\n";
  }
  svg << "</svg>\n";
  writeFileAtomically(path, svg.str());
}

void writeCellPolygons(const IceSheet& sheet, const std::string& path) {
  std::ostringstream out;
  out << std::setprecision(12);
  out << "# index n x0 y0 x1 y1 ... [m], counter-clockwise\n";
  for (size_t i = 0; i < sheet.cells.size(); ++i) {
    const CellGeometry& c = sheet.cells[i];
    out << i << ' ' << c.vertices.size();
    for (const Vec2& v : c.vertices) out << ' ' << c.centroid.x + v.x << ' ' << c.centroid.y + v.y;
    out << '\n';
  }
  writeFileAtomically(path, out.str());
}

}  // namespace thin_ice
