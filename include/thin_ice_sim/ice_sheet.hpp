// The intact ice sheet at t = 0: a rectangle cut into convex Voronoi cells (paper Section 2.1,
// Fig. 1), and the shared edges between them that become RMIB bonds (Section 2.6).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

enum class SeedLayout {
  kJitteredGrid,  ///< square grid of pitch cell_size, each seed moved by up to jitter * cell_size
  kPoissonDisk,   ///< Bridson's Poisson-disk sampling with the same mean density
};

/// Parses "jittered_grid" or "poisson_disk"; throws std::invalid_argument naming `key` otherwise.
SeedLayout parseSeedLayout(const std::string& text, const std::string& key);
std::string toString(SeedLayout layout);

struct IceSheetSpec {
  double length = 10.0;       ///< [m] extent along x (towards the structure)
  double width = 2.0;         ///< [m] extent along y; the sheet spans y in [-width/2, width/2]
  double x_min = 0.0;         ///< [m] x of the rear edge (the pusher side)
  double cell_size = 0.2;     ///< [m] target sqrt(mean cell area)
  SeedLayout layout = SeedLayout::kJitteredGrid;
  double jitter = 0.35;       ///< [-] grid jitter as a fraction of cell_size, in [0, 0.5]
  int lloyd_iterations = 3;   ///< [-] Lloyd relaxation steps, in [0, 50]
  std::uint64_t seed = 1;     ///< random seed: the same seed gives the same sheet
};

/// Throws std::invalid_argument with a message naming the parameter, its value and the allowed
/// range when the spec cannot make a sheet.
void validate(const IceSheetSpec& spec);

struct CellGeometry {
  Vec2 centroid;                    ///< [m] world frame at t = 0
  double area = 0.0;                ///< [m^2]
  double polar_moment = 0.0;        ///< J [m^4]: polar second moment of area about the centroid
  std::vector<Vec2> vertices;       ///< (n x 2) [m] offsets from the centroid, counter-clockwise
  std::vector<int> edge_neighbour;  ///< (n) cell across edge k (vertex k -> k+1), -1 on the rim
};

/// A Voronoi edge shared by two cells: a future bond.
struct SharedEdge {
  int i = -1;           ///< lower cell index
  int j = -1;           ///< higher cell index
  double length = 0.0;  ///< [m]
  Vec2 start;           ///< [m] world endpoints at t = 0, as seen from cell i
  Vec2 end;             ///< [m]
  Vec2 midpoint() const { return 0.5 * (start + end); }
};

struct IceSheet {
  IceSheetSpec spec;
  std::vector<CellGeometry> cells;
  std::vector<SharedEdge> edges;  ///< sorted by (i, j)
};

/// Generates the sheet: seeds, `lloyd_iterations` Lloyd steps, Voronoi cells from CGAL's Delaunay
/// triangulation clipped to the rectangle. Deterministic for a given spec.
IceSheet generateIceSheet(const IceSheetSpec& spec);

/// Centroid, area and polar moment of a counter-clockwise polygon given in world coordinates;
/// `vertices` becomes offsets from the centroid.
void setCellGeometryFromPolygon(const std::vector<Vec2>& world_vertices, CellGeometry& cell);

struct IceSheetStats {
  int cell_count = 0;
  int edge_count = 0;
  double total_area = 0.0;        ///< [m^2]
  double mean_cell_area = 0.0;    ///< [m^2]
  double mean_cell_size = 0.0;    ///< [m] sqrt(mean area)
  double min_cell_area = 0.0;     ///< [m^2]
  double max_cell_area = 0.0;     ///< [m^2]
  double mean_edge_length = 0.0;  ///< [m] l-bar of Algorithm 1 (shared edges only)
  int min_vertices = 0;
  int max_vertices = 0;
  double mean_neighbours = 0.0;   ///< shared edges per cell
};

IceSheetStats computeStats(const IceSheet& sheet);

}  // namespace thin_ice
