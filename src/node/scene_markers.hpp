// rviz markers of the scene: the cells (filled polygons with outlines, coloured by state), the
// inclined structure with its side panels, the load on it, the pusher plate and the false bottom.
#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

/// Marker namespaces: "cells" (triangle list), "outlines" (line list), "structure" (the face),
/// "side_panels" (translucent), "load" (an arrow of F_cal, its head on the face at half its height,
/// load_arrow_scale [m per N/m of structure width] long; deleted while shorter than its head),
/// "pusher", "bottom", "readout" (t, L, F_cal, the real-time factor given, broken bonds) and
/// "legend" (text). Cells are drawn at their top surface; intact sheet
/// light grey-blue, broken pieces coloured by the height of their top above the waterline (blue at
/// 0, red at 0.3 m and above).
visualization_msgs::MarkerArray makeSceneMarkers(const Simulation& sim, const std::string& frame,
                                                 const ros::Time& stamp, double real_time_factor,
                                                 double load_arrow_scale);

}  // namespace thin_ice
