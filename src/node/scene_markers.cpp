#include "scene_markers.hpp"

#include <geometry_msgs/Point.h>
#include <std_msgs/ColorRGBA.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "thin_ice_sim/model.hpp"  // ModelConstants: the scene as the laws use it

namespace thin_ice {
namespace {

constexpr double kRedAbove = 0.3;  ///< [m] top height above the waterline drawn fully red

geometry_msgs::Point point(double x, double y, double z) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

std_msgs::ColorRGBA colour(double r, double g, double b, double a = 1.0) {
  std_msgs::ColorRGBA c;
  c.r = static_cast<float>(r);
  c.g = static_cast<float>(g);
  c.b = static_cast<float>(b);
  c.a = static_cast<float>(a);
  return c;
}

visualization_msgs::Marker baseMarker(const std::string& frame, const ros::Time& stamp, const std::string& ns,
                                      int type) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = 0;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color = colour(1, 1, 1);
  return m;
}

/// The quadrilateral a-b-c-d as triangles of both windings, so that rviz lights it from either side.
void addQuad(visualization_msgs::Marker& m, const geometry_msgs::Point& a, const geometry_msgs::Point& b,
             const geometry_msgs::Point& c, const geometry_msgs::Point& d) {
  m.points.insert(m.points.end(), {a, b, c, a, c, d, a, c, b, a, d, c});
}

}  // namespace

visualization_msgs::MarkerArray makeSceneMarkers(const Simulation& sim, const std::string& frame,
                                                 const ros::Time& stamp, double real_time_factor,
                                                 double load_arrow_scale) {
  const Params& p = sim.params();
  const LoadSample l = sim.loads();
  const double half_h = 0.5 * p.ice.thickness;
  visualization_msgs::MarkerArray array;

  visualization_msgs::Marker cells = baseMarker(frame, stamp, "cells", visualization_msgs::Marker::TRIANGLE_LIST);
  visualization_msgs::Marker outlines = baseMarker(frame, stamp, "outlines", visualization_msgs::Marker::LINE_LIST);
  outlines.scale.x = 0.008;  // [m] line width
  outlines.color = colour(0.15, 0.25, 0.35);
  const std::vector<CellSnapshot> states = sim.cells();
  for (int k = 0; k < sim.cellCount(); ++k) {
    const CellSnapshot& c = states[k];
    const std::vector<Vec2> polygon = sim.cellPolygon(k, c);
    const double top = c.z + half_h;
    std_msgs::ColorRGBA fill = colour(0.86, 0.92, 0.97);
    if (!c.in_intact_sheet) {
      const double t = std::clamp(top / kRedAbove, 0.0, 1.0);
      fill = colour(0.25 + 0.75 * t, 0.55 - 0.2 * t, 0.9 - 0.7 * t);
    }
    for (size_t v = 1; v + 1 < polygon.size(); ++v) {
      cells.points.push_back(point(polygon[0].x, polygon[0].y, top));
      cells.points.push_back(point(polygon[v].x, polygon[v].y, top));
      cells.points.push_back(point(polygon[v + 1].x, polygon[v + 1].y, top));
      cells.colors.insert(cells.colors.end(), {fill, fill, fill});
    }
    for (size_t v = 0; v < polygon.size(); ++v) {
      const Vec2 a = polygon[v], b = polygon[(v + 1) % polygon.size()];
      outlines.points.push_back(point(a.x, a.y, top + 0.001));
      outlines.points.push_back(point(b.x, b.y, top + 0.001));
    }
  }
  array.markers.push_back(cells);
  array.markers.push_back(outlines);

  // The structure: the inclined face from the bottom to its top, and the side panels.
  const StructureParams& s = p.structure;
  const double z_low = sim.scene().bottom_z, z_high = s.height;
  const double x_low = structureFaceX(s, z_low), x_high = structureFaceX(s, z_high);
  const double y0 = -0.5 * s.width, y1 = 0.5 * s.width;
  visualization_msgs::Marker structure = baseMarker(frame, stamp, "structure", visualization_msgs::Marker::TRIANGLE_LIST);
  structure.color = colour(0.55, 0.55, 0.6, 0.6);  // the pile behind the face shows through
  addQuad(structure, point(x_low, y0, z_low), point(x_low, y1, z_low), point(x_high, y1, z_high), point(x_high, y0, z_high));
  array.markers.push_back(structure);
  // The side panels translucent, so that they do not hide the face and the pile from the side.
  visualization_msgs::Marker panels = baseMarker(frame, stamp, "side_panels", visualization_msgs::Marker::TRIANGLE_LIST);
  panels.color = colour(0.55, 0.55, 0.6, 0.3);
  for (const double y : {y0, y1}) {
    addQuad(panels, point(s.toe_x - s.side_panel_length, y, z_low), point(x_high, y, z_low),
            point(x_high, y, z_high), point(s.toe_x - s.side_panel_length, y, z_high));
  }
  array.markers.push_back(panels);
  // A readout, a legend and the load arrow, sized with the lane so that they read at full width and
  // on a 1 m strip alike.
  const double lane = p.channel.enabled ? p.channel.width : p.sheet.width;  // [m]
  const double text_height = std::max(0.1, 0.03 * lane);                      // [m]

  // The load on the structure, F_cal = alpha F (Eq. 18) in all three components, as the wrench
  // carries it: an arrow whose head presses on the face at half its height. The wrench's own frame
  // (the toe, on the waterline) lies behind the face and under the pile, where nothing shows.
  visualization_msgs::Marker arrow = baseMarker(frame, stamp, "load", visualization_msgs::Marker::ARROW);
  const double metres_per_newton = load_arrow_scale / s.width;  // [m/N]: load_arrow_scale is per N/m of width
  const CalibratedWrench load = calibratedTotal(l, p.structure.calibration_factor);
  const double fx = load.fx, fy = load.fy, fz = load.fz;  // [N]
  const double arrow_length = std::sqrt(fx * fx + fy * fy + fz * fz) * metres_per_newton;               // [m]
  arrow.scale.x = 0.3 * text_height;  // shaft diameter [m]
  arrow.scale.y = 0.6 * text_height;  // head diameter [m]
  arrow.scale.z = 0.8 * text_height;  // head length [m]
  arrow.color = colour(0.8, 0.16, 0.8);
  if (arrow_length > arrow.scale.z) {
    const double z_head = 0.5 * z_high;
    const geometry_msgs::Point head = point(structureFaceX(s, z_head), 0.0, z_head);
    arrow.points = {point(head.x - fx * metres_per_newton, head.y - fy * metres_per_newton,
                          head.z - fz * metres_per_newton),
                    head};
  } else {
    arrow.action = visualization_msgs::Marker::DELETE;  // too short to draw: the last one goes
  }
  array.markers.push_back(arrow);

  visualization_msgs::Marker pusher = baseMarker(frame, stamp, "pusher", visualization_msgs::Marker::CUBE);
  pusher.pose.position = point(sim.pusherPosition() - 0.02, 0.0, 0.0);
  pusher.scale.x = 0.04;
  pusher.scale.y = lane;
  pusher.scale.z = 0.4;
  pusher.color = colour(0.9, 0.6, 0.1);
  array.markers.push_back(pusher);

  if (p.bottom.enabled) {
    const double x_start = sim.scene().bottom_x_start;
    visualization_msgs::Marker bottom = baseMarker(frame, stamp, "bottom", visualization_msgs::Marker::CUBE);
    bottom.pose.position = point(0.5 * (x_start + x_high), 0.0, z_low - 0.01);
    bottom.scale.x = x_high - x_start;
    bottom.scale.y = s.width;
    bottom.scale.z = 0.02;
    bottom.color = colour(0.45, 0.35, 0.25, 0.8);
    array.markers.push_back(bottom);
  }
  // A readout above the structure and a legend beside it, facing the camera.
  char pace[32];
  if (sim.paused()) {
    std::snprintf(pace, sizeof pace, "paused");
  } else {
    std::snprintf(pace, sizeof pace, "%.3gx real time", real_time_factor);
  }
  char readout[256];
  std::snprintf(readout, sizeof readout, "t %.2f s   L %.3f m   F_cal %.0f N   %s   broken bonds %d of %d",
                sim.time(), sim.pushedLength(), l.horizontal_calibrated, pace,
                l.broken_bonds, l.broken_bonds + l.intact_bonds);
  visualization_msgs::Marker text = baseMarker(frame, stamp, "readout", visualization_msgs::Marker::TEXT_VIEW_FACING);
  text.pose.position = point(x_high, 0.0, z_high + 3.0 * text_height);
  text.scale.z = text_height;
  text.text = readout;
  array.markers.push_back(text);
  visualization_msgs::Marker legend = baseMarker(frame, stamp, "legend", visualization_msgs::Marker::TEXT_VIEW_FACING);
  legend.pose.position = point(x_high, 0.0, z_high + 1.5 * text_height);
  legend.scale.z = 0.7 * text_height;
  legend.color = colour(0.85, 0.85, 0.85);
  char arrow_legend[64] = "";  // none without an arrow (~load_arrow_scale 0)
  if (load_arrow_scale > 0.0) {
    std::snprintf(arrow_legend, sizeof arrow_legend, "   magenta: F_cal, %.3g m per kN/m of width", 1e3 * load_arrow_scale);
  }
  char legend_text[256];
  std::snprintf(legend_text, sizeof legend_text,
                "pale: intact sheet   blue to red: broken ice, top 0 to 0.3 m above water\n"
                "orange: pusher   brown: false bottom%s",
                arrow_legend);
  legend.text = legend_text;
  array.markers.push_back(legend);
  return array;
}

}  // namespace thin_ice
