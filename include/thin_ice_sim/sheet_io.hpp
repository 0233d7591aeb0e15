// Writing an ice sheet for people and plots: an SVG picture and a plain polygon list.
#pragma once

#include <string>

#include "thin_ice_sim/ice_sheet.hpp"

namespace thin_ice {

/// SVG picture of the cells (filled, outlined) and their bonds; x to the right, y up.
/// Written to a temporary file and renamed, so a failure leaves no half-written picture.
void writeSheetSvg(const IceSheet& sheet, const std::string& path);

/// One line per cell: "index n x0 y0 x1 y1 ..." with world vertices [m], counter-clockwise.
void writeCellPolygons(const IceSheet& sheet, const std::string& path);

/// Writes `text` to `path` through a temporary file and a rename; throws std::runtime_error
/// naming the path when it cannot.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace thin_ice
