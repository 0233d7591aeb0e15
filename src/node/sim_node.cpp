#include "sim_node.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <rosgraph_msgs/Clock.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "scene_markers.hpp"
#include "thin_ice_sim/PanelLoads.h"
#include "thin_ice_sim/SimStatus.h"
#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {
namespace {

/// [s of wall time] between two "falling behind" warnings.
constexpr double kBehindWarningPeriod = 10.0;

/// Where bare scenario names are looked up (the package's config/scenarios, set by CMake).
const std::string kScenarioDir = THIN_ICE_SCENARIO_DIR;

std::string resolveScenario(const std::string& name) {
  const bool has_yaml_suffix = name.size() > 5 && name.substr(name.size() - 5) == ".yaml";
  if (name.find('/') != std::string::npos || has_yaml_suffix) {
    // A relative path is taken from the node's working directory, which under roslaunch is
    // ~/.ros: made absolute here, so that a "no such file" message says where it looked.
    return std::filesystem::absolute(name).lexically_normal().string();
  }
  return kScenarioDir + "/" + name + ".yaml";
}

void requireRange(const std::string& name, double value, double low, double high, bool allow_zero,
                  const std::string& why) {
  const bool zero_ok = allow_zero && value == 0.0;
  if (!std::isfinite(value) || !(zero_ok || (value >= low && value <= high))) {
    std::ostringstream msg;
    msg << "parameter ~" << name << " = " << value << " is invalid; allowed: " << (allow_zero ? "0 or " : "") << low
        << " to " << high << why;
    throw std::invalid_argument(msg.str());
  }
}

std::string describe(XmlRpc::XmlRpcValue& value) {
  std::ostringstream text;
  value.write(text);
  return text.str();
}

std::string typeName(const XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return "a boolean";
    case XmlRpc::XmlRpcValue::TypeInt: return "an integer";
    case XmlRpc::XmlRpcValue::TypeDouble: return "a number";
    case XmlRpc::XmlRpcValue::TypeString: return "a string";
    case XmlRpc::XmlRpcValue::TypeArray: return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct: return "a dictionary";
    default: return "of another type";
  }
}

[[noreturn]] void wrongType(const std::string& name, XmlRpc::XmlRpcValue& value, const std::string& allowed) {
  throw std::invalid_argument("parameter ~" + name + " = " + describe(value) + " is " + typeName(value) +
                              "; allowed: " + allowed);
}

// NodeHandle::param falls back to the default when the stored value has another type (paused:=1
// is an integer, not a boolean), so a mistyped parameter would be ignored without a word. These
// read the value as stored and accept only what can stand for the type without guessing.
void readParam(const ros::NodeHandle& pnh, const std::string& name, double& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    out = static_cast<double>(value);
  } else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    out = static_cast<int>(value);
  } else {
    wrongType(name, value, "a number");
  }
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, bool& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeBoolean) {
    out = static_cast<bool>(value);
  } else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt && (static_cast<int>(value) == 0 || static_cast<int>(value) == 1)) {
    out = static_cast<int>(value) == 1;
  } else {
    wrongType(name, value, "true or false (or 1 or 0)");
  }
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, std::string& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) wrongType(name, value, "a string");
  out = static_cast<std::string>(value);
}

void readParam(const ros::NodeHandle& pnh, const std::string& name, long& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeInt) wrongType(name, value, "a whole number");
  out = static_cast<int>(value);
}

geometry_msgs::Vector3 vector3(double x, double y, double z) {
  geometry_msgs::Vector3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

}  // namespace

NodeSettings readNodeSettings(const ros::NodeHandle& pnh) {
  NodeSettings s;
  readParam(pnh, "scenario", s.scenario);
  if (s.scenario.empty()) {
    throw std::invalid_argument("parameter ~scenario is required: a name in " + kScenarioDir + " or a path");
  }
  s.scenario = resolveScenario(s.scenario);
  // ~set: a list of "section.key=value" strings, or one string of them separated by spaces.
  XmlRpc::XmlRpcValue set;
  if (pnh.getParam("set", set)) {
    if (set.getType() == XmlRpc::XmlRpcValue::TypeArray) {
      for (int k = 0; k < set.size(); ++k) {
        if (set[k].getType() != XmlRpc::XmlRpcValue::TypeString) {
          wrongType("set item " + std::to_string(k), set[k], "a 'section.key=value' string");
        }
        s.overrides.push_back(static_cast<std::string>(set[k]));
      }
    } else if (set.getType() == XmlRpc::XmlRpcValue::TypeString) {
      std::istringstream words(static_cast<std::string>(set));
      for (std::string w; words >> w;) s.overrides.push_back(w);
    } else {
      wrongType("set", set, "a list of 'section.key=value' strings or one such string");
    }
  }
  readParam(pnh, "backend", s.backend);
  readParam(pnh, "real_time_factor", s.real_time_factor);
  readParam(pnh, "load_rate", s.load_rate);
  readParam(pnh, "marker_rate", s.marker_rate);
  readParam(pnh, "status_rate", s.status_rate);
  readParam(pnh, "publish_clock", s.publish_clock);
  readParam(pnh, "cmd_timeout", s.cmd_timeout);
  readParam(pnh, "paused_clock_rate", s.paused_clock_rate);
  readParam(pnh, "load_arrow_scale", s.load_arrow_scale);
  readParam(pnh, "max_pusher_speed", s.max_pusher_speed);
  readParam(pnh, "max_steps_per_call", s.max_steps_per_call);
  readParam(pnh, "paused", s.start_paused);
  readParam(pnh, "stop_time", s.stop_time);
  readParam(pnh, "world_frame", s.world_frame);
  readParam(pnh, "structure_frame", s.structure_frame);
  readParam(pnh, "pusher_frame", s.pusher_frame);
  const NodeLimits& l = kNodeLimits;
  requireRange("real_time_factor", s.real_time_factor, l.min_real_time_factor, l.max_real_time_factor, true,
               " (0: as fast as possible)");
  requireRange("load_rate", s.load_rate, l.min_load_rate, l.max_load_rate, false,
               " Hz of simulated time (each load period is simulated in one call that nothing interrupts)");
  requireRange("marker_rate", s.marker_rate, l.min_wall_rate, l.max_wall_rate, false, " Hz");
  requireRange("status_rate", s.status_rate, l.min_wall_rate, l.max_wall_rate, false, " Hz");
  requireRange("cmd_timeout", s.cmd_timeout, l.min_cmd_timeout, l.max_cmd_timeout, true,
               " s of simulated time (0: never)");
  requireRange("paused_clock_rate", s.paused_clock_rate, l.min_wall_rate, l.max_wall_rate, false, " Hz");
  requireRange("load_arrow_scale", s.load_arrow_scale, l.min_load_arrow_scale, l.max_load_arrow_scale, true,
               " m per N/m of structure width (0: no load arrow)");
  requireRange("max_pusher_speed", s.max_pusher_speed, l.min_pusher_speed, l.max_pusher_speed, false, " m/s");
  requireRange("max_steps_per_call", static_cast<double>(s.max_steps_per_call), 1.0, l.max_steps_per_call, false,
               " time steps");
  requireRange("stop_time", s.stop_time, l.min_stop_time, l.max_stop_time, true, " s (0: never)");
  parseBackendKind(s.backend, "parameter ~backend");
  return s;
}

SimNode::SimNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), private_nh_(private_nh), settings_(readNodeSettings(private_nh_)) {
  const Scenario scenario = loadScenario(settings_.scenario, settings_.overrides);
  if (std::fabs(scenario.params.pusher.velocity) > settings_.max_pusher_speed) {
    std::ostringstream msg;
    msg << settings_.scenario << ": pusher.velocity = " << scenario.params.pusher.velocity
        << " m/s is faster than ~max_pusher_speed = " << settings_.max_pusher_speed
        << " m/s; allowed: |pusher.velocity| <= ~max_pusher_speed (raise the parameter or lower the velocity)";
    throw std::invalid_argument(msg.str());
  }
  sim_ = std::make_unique<Simulation>(scenario, parseBackendKind(settings_.backend, "~backend"));
  ROS_INFO("thin_ice_sim: scenario %s (%d cells, dt %.3g s, critical %.3g s, structure contact in %d sub-steps), %s, "
           "CPU code built for %s",
           settings_.scenario.c_str(), sim_->cellCount(), sim_->timeStep(), sim_->criticalTimeStep(),
           sim_->structureSubsteps(), sim_->backendNote().c_str(), Simulation::cpuInstructionSet());
  if (settings_.start_paused) sim_->pause();
  applied_velocity_ = sim_->pusherVelocity();

  wrench_pub_ = nh_.advertise<geometry_msgs::WrenchStamped>("structure/wrench", 50);
  panels_pub_ = nh_.advertise<thin_ice_sim::PanelLoads>("structure/panel_loads", 50);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("ice/cells", 2);
  status_pub_ = nh_.advertise<thin_ice_sim::SimStatus>("sim/status", 10);
  if (settings_.publish_clock) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 50);
  command_sub_ = nh_.subscribe("pusher/cmd_vel", 10, &SimNode::onCommand, this);
  pause_srv_ = nh_.advertiseService("sim/pause", &SimNode::onPause, this);
  unpause_srv_ = nh_.advertiseService("sim/unpause", &SimNode::onUnpause, this);
  unpause_checked_srv_ = nh_.advertiseService("sim/unpause_checked", &SimNode::onUnpauseChecked, this);
  reset_srv_ = nh_.advertiseService("sim/reset", &SimNode::onReset, this);
  step_srv_ = nh_.advertiseService("sim/step", &SimNode::onStep, this);
  publishStructureTransform();
  // Started with the values checked above (the server would otherwise begin at the .cfg defaults).
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<thin_ice_sim::SimConfig>>(reconfigure_mutex_, private_nh_);
  thin_ice_sim::SimConfig now;
  now.real_time_factor = settings_.real_time_factor;
  now.max_pusher_speed = settings_.max_pusher_speed;
  now.cmd_timeout = settings_.cmd_timeout;
  now.marker_rate = settings_.marker_rate;
  reconfigure_->updateConfig(now);
  reconfigure_->setCallback([this](thin_ice_sim::SimConfig& c, uint32_t level) { onReconfigure(c, level); });
}

void SimNode::onReconfigure(thin_ice_sim::SimConfig& config, uint32_t) {
  const NodeLimits& l = kNodeLimits;
  NodeSettings wanted = settings_;
  wanted.real_time_factor = config.real_time_factor;
  wanted.max_pusher_speed = config.max_pusher_speed;
  wanted.cmd_timeout = config.cmd_timeout;
  wanted.marker_rate = config.marker_rate;
  try {
    requireRange("real_time_factor", wanted.real_time_factor, l.min_real_time_factor, l.max_real_time_factor, true,
                 " (0: as fast as possible)");
    requireRange("max_pusher_speed", wanted.max_pusher_speed, l.min_pusher_speed, l.max_pusher_speed, false, " m/s");
    requireRange("cmd_timeout", wanted.cmd_timeout, l.min_cmd_timeout, l.max_cmd_timeout, true,
                 " s of simulated time (0: never)");
    requireRange("marker_rate", wanted.marker_rate, l.min_wall_rate, l.max_wall_rate, false, " Hz");
    if (std::fabs(sim_->params().pusher.velocity) > wanted.max_pusher_speed && !have_command_) {
      throw std::invalid_argument("~max_pusher_speed = " + std::to_string(wanted.max_pusher_speed) +
                                  " m/s is below the scenario's pusher.velocity, which drives the pusher until the "
                                  "first command");
    }
  } catch (const std::invalid_argument& e) {
    ROS_WARN("thin_ice_sim: reconfigure refused, nothing changed: %s", e.what());
    config.real_time_factor = settings_.real_time_factor;
    config.max_pusher_speed = settings_.max_pusher_speed;
    config.cmd_timeout = settings_.cmd_timeout;
    config.marker_rate = settings_.marker_rate;
    return;
  }
  if (wanted.real_time_factor != settings_.real_time_factor) {
    // Pacing starts again from here, as after a pause.
    rtf_window_start_ = ros::WallTime::now();
    rtf_window_sim_start_ = sim_->time();
    repace_ = true;
  }
  settings_ = wanted;
  if (have_command_ && std::fabs(command_velocity_) > settings_.max_pusher_speed) {
    command_velocity_ = std::copysign(settings_.max_pusher_speed, command_velocity_);
  }
  ROS_INFO("thin_ice_sim: reconfigured: real_time_factor %.3g, max_pusher_speed %.3g m/s, cmd_timeout %.3g s, "
           "marker_rate %.3g Hz", settings_.real_time_factor, settings_.max_pusher_speed, settings_.cmd_timeout,
           settings_.marker_rate);
}

void SimNode::onCommand(const geometry_msgs::Twist& command) {
  const double v = command.linear.x;
  if (!std::isfinite(v)) {
    ROS_WARN_THROTTLE(1.0, "thin_ice_sim: dropped a pusher command with a non-finite linear.x");
    return;
  }
  double accepted = v;
  if (std::fabs(v) > settings_.max_pusher_speed) {
    accepted = std::copysign(settings_.max_pusher_speed, v);
    ROS_WARN_THROTTLE(1.0, "thin_ice_sim: pusher command %.4g m/s clamped to %.4g m/s (~max_pusher_speed)", v,
                      accepted);
  }
  command_velocity_ = accepted;
  command_sim_time_ = sim_->time();
  have_command_ = true;
  command_expired_ = false;
}

double SimNode::commandedVelocity() {
  if (!have_command_) return sim_->params().pusher.velocity;
  if (settings_.cmd_timeout > 0.0 && sim_->time() - command_sim_time_ > settings_.cmd_timeout) {
    if (!command_expired_) {
      ROS_WARN("thin_ice_sim: no pusher command for %.3g s of simulated time (~cmd_timeout): pusher stopped",
               settings_.cmd_timeout);
      command_expired_ = true;
    }
    return 0.0;
  }
  return command_velocity_;
}

bool SimNode::onPause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  sim_->pause();
  return true;
}

std::string SimNode::unpause() {
  if (!sim_->healthy()) {
    const std::string why = "cannot unpause after a numerical blow-up (" + sim_->lastError() + "); call sim/reset";
    ROS_WARN("thin_ice_sim: %s", why.c_str());
    publishStatus();  // paused, with last_error: what a client of the Empty service can read
    return why;
  }
  sim_->resume();
  rtf_window_start_ = ros::WallTime::now();
  rtf_window_sim_start_ = sim_->time();
  return "";
}

bool SimNode::onUnpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  unpause();
  return true;  // as Gazebo: the call succeeds; a refusal is in the log and in sim/status
}

bool SimNode::onUnpauseChecked(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  // Answered, not failed: a failed call reaches the client as an exception without the reason.
  const std::string why = unpause();
  response.success = why.empty();
  response.message = why.empty() ? "running" : why;
  return true;
}

bool SimNode::onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  sim_->reset();
  have_command_ = false;
  last_error_.clear();
  applied_velocity_ = sim_->pusherVelocity();
  rtf_window_start_ = ros::WallTime::now();
  rtf_window_sim_start_ = 0.0;
  publishStatus();
  return true;
}

bool SimNode::onStep(thin_ice_sim::Step::Request& request, thin_ice_sim::Step::Response& response) {
  response.success = false;
  // Counted in double first: a huge duration, or a steps field of 2^32 - 1 sent for -1, is refused
  // rather than cast into a long that overflows or a call that blocks the node for days. A duration
  // rounds up to whole steps, so any positive one is at least one step (1e-300 s answered "stepped
  // 0 steps"); the 1e-9 keeps a duration of whole steps from gaining one by rounding.
  const double wanted = request.duration > 0.0
                            ? std::max(1.0, std::ceil(request.duration / sim_->timeStep() - 1e-9))
                            : static_cast<double>(request.steps);
  if (!sim_->paused()) {
    response.message = "sim/step needs a paused simulation (call sim/pause first)";
  } else if (!std::isfinite(request.duration) || request.duration < 0.0) {
    response.message = "duration must be finite and >= 0 s";
  } else if (!sim_->healthy()) {
    response.message = "the simulation blew up: " + sim_->lastError() + "; call sim/reset";
  } else if (wanted > static_cast<double>(settings_.max_steps_per_call)) {
    std::ostringstream msg;
    msg << "the request is " << wanted << " time steps (dt = " << sim_->timeStep()
        << " s); allowed: at most ~max_steps_per_call = " << settings_.max_steps_per_call
        << " per call (the node serves nothing else while it steps): step in several calls";
    response.message = msg.str();
  } else {
    const long steps = static_cast<long>(wanted);
    if (steps > 0) stepPublishingEachPeriod(steps);
    response.success = sim_->healthy();
    response.message = sim_->healthy() ? "stepped " + std::to_string(steps) + " steps" : sim_->lastError();
  }
  response.sim_time = sim_->time();
  publishStatus();
  return true;
}

void SimNode::stepPublishingEachPeriod(long steps) {
  // Steps of one load period: 1/load_rate of simulated time, at least one step.
  const long per_period = std::max(1L, std::lround(1.0 / (settings_.load_rate * sim_->timeStep())));
  for (long left = steps; left > 0 && sim_->healthy();) {
    const long now = std::min(left, per_period);
    sim_->setPusherVelocity(applied_velocity_ = commandedVelocity());
    sim_->step(now);
    left -= now;
    checkHealth();
    if (!sim_->healthy()) break;
    publishLoads();
    publishClockAndTf();
  }
}

void SimNode::checkHealth() {
  if (sim_->healthy() || sim_->lastError() == last_error_) return;
  last_error_ = sim_->lastError();
  sim_->pause();
  ROS_ERROR("thin_ice_sim: %s; simulation paused (sim/reset to start again)", last_error_.c_str());
}

void SimNode::advanceAndPublish() {
  sim_->setPusherVelocity(applied_velocity_ = commandedVelocity());
  sim_->advance(1.0 / settings_.load_rate);
  checkHealth();
  if (!sim_->healthy()) return;
  publishLoads();
  publishClockAndTf();
}

void SimNode::publishLoads() {
  const LoadSample l = sim_->loads();
  const double alpha = sim_->params().structure.calibration_factor;
  const ros::Time stamp(sim_->time());
  geometry_msgs::WrenchStamped wrench;
  wrench.header.stamp = stamp;
  wrench.header.frame_id = settings_.structure_frame;
  const CalibratedWrench total = calibratedTotal(l, alpha);
  wrench.wrench.force = vector3(total.fx, total.fy, total.fz);
  wrench.wrench.torque = vector3(total.torque.x, total.torque.y, total.torque.z);
  wrench_pub_.publish(wrench);

  thin_ice_sim::PanelLoads panels;
  panels.header = wrench.header;
  panels.calibration_factor = alpha;
  const StructureParams& s = sim_->params().structure;
  for (int p = 0; p < static_cast<int>(l.panel_horizontal.size()); ++p) {
    const CalibratedWrench panel = calibratedPanel(l, p, alpha);
    geometry_msgs::Wrench w;
    w.force = vector3(panel.fx, panel.fy, panel.fz);
    w.torque = vector3(panel.torque.x, panel.torque.y, panel.torque.z);
    panels.panels.push_back(w);
    panels.panel_centre_y.push_back(-0.5 * s.width + (p + 0.5) * s.width / s.panels);
  }
  panels_pub_.publish(panels);
}

void SimNode::publishClockAndTf() {
  const ros::Time stamp(sim_->time());
  if (settings_.publish_clock) {
    rosgraph_msgs::Clock clock;
    clock.clock = stamp;
    clock_pub_.publish(clock);
  }
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = settings_.world_frame;
  t.child_frame_id = settings_.pusher_frame;
  t.transform.translation.x = sim_->pusherPosition();
  t.transform.rotation.w = 1.0;
  tf_.sendTransform(t);
}

void SimNode::publishStructureTransform() {
  // The structure frame: origin where the face meets the waterline at y = 0, axes as the world's.
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time(0.0);
  t.header.frame_id = settings_.world_frame;
  t.child_frame_id = settings_.structure_frame;
  t.transform.translation.x = sim_->params().structure.toe_x;
  t.transform.rotation.w = 1.0;
  static_tf_.sendTransform(t);
}

void SimNode::publishStatus() {
  const LoadSample l = sim_->loads();
  thin_ice_sim::SimStatus status;
  status.header.stamp = ros::Time(sim_->time());
  status.header.frame_id = settings_.world_frame;
  status.sim_time = sim_->time();
  status.pushed_length = sim_->pushedLength();
  // At the end of its travel (the structure's toe) the plate stands whatever it is told.
  const bool stopped_at_toe = sim_->pusherAtTravelEnd() && applied_velocity_ > 0.0;
  status.pusher_velocity = stopped_at_toe ? 0.0 : applied_velocity_;
  if (stopped_at_toe && !reported_travel_end_) {
    ROS_WARN("thin_ice_sim: the pusher has reached the end of its travel (its face at the structure's toe, L = %.3f m): "
             "it stays there until told to back off", sim_->pusherTravel());
  }
  reported_travel_end_ = stopped_at_toe;
  status.real_time_factor = achieved_rtf_;
  status.cells = static_cast<uint32_t>(sim_->cellCount());
  status.intact_bonds = static_cast<uint32_t>(l.intact_bonds);
  status.broken_bonds = static_cast<uint32_t>(l.broken_bonds);
  status.contacts = static_cast<uint32_t>(l.contacts);
  status.backend = sim_->backendName();
  status.paused = sim_->paused();
  status.last_error = sim_->lastError();
  status_pub_.publish(status);
}

void SimNode::publishMarkers() {
  if (markers_pub_.getNumSubscribers() == 0) return;
  markers_pub_.publish(makeSceneMarkers(*sim_, settings_.world_frame, ros::Time(sim_->time()), achieved_rtf_,
                                        settings_.load_arrow_scale));
}

void SimNode::run() {
  ros::WallTime pace_start = ros::WallTime::now();
  double pace_sim_start = sim_->time();
  rtf_window_start_ = pace_start;
  rtf_window_sim_start_ = pace_sim_start;
  next_marker_time_ = next_status_time_ = pace_start;
  bool was_paused = true;
  while (ros::ok()) {
    ros::spinOnce();
    const ros::WallTime now = ros::WallTime::now();
    if (now >= next_status_time_) {
      publishStatus();
      next_status_time_ = now + ros::WallDuration(1.0 / settings_.status_rate);
    }
    if (now >= next_marker_time_) {
      publishMarkers();
      next_marker_time_ = now + ros::WallDuration(1.0 / settings_.marker_rate);
    }
    if (sim_->paused()) {
      was_paused = true;
      achieved_rtf_ = 0.0;
      // The frozen clock goes on, as Gazebo's: a node on simulated time started now has a time.
      if (settings_.publish_clock && now >= next_paused_clock_time_) {
        rosgraph_msgs::Clock clock;
        clock.clock = ros::Time(sim_->time());
        clock_pub_.publish(clock);
        next_paused_clock_time_ = now + ros::WallDuration(1.0 / settings_.paused_clock_rate);
      }
      ros::WallDuration(0.005).sleep();
      continue;
    }
    if (was_paused || repace_) {  // pacing restarts after a pause, a reset, the first step or a new factor
      repace_ = false;
      pace_start = now;
      pace_sim_start = sim_->time();
      was_paused = false;
    }
    advanceAndPublish();
    if (settings_.stop_time > 0.0 && sim_->time() >= settings_.stop_time - 1e-12) {
      publishStatus();
      ROS_INFO("thin_ice_sim: reached ~stop_time = %.6g s of simulated time: finished", settings_.stop_time);
      ros::shutdown();
      break;
    }
    // Achieved real-time factor over windows of about one second of wall time.
    const ros::WallTime after = ros::WallTime::now();
    const double window = (after - rtf_window_start_).toSec();
    if (window >= 1.0) {
      achieved_rtf_ = (sim_->time() - rtf_window_sim_start_) / window;
      rtf_window_start_ = after;
      rtf_window_sim_start_ = sim_->time();
      // Throttled on wall time: ROS_WARN_THROTTLE counts ros::Time, which under use_sim_time is
      // this node's own slow clock (at 0.05x real time it said nothing for minutes).
      if (settings_.real_time_factor > 0.0 && achieved_rtf_ < 0.9 * settings_.real_time_factor &&
          (last_behind_warning_.isZero() || (after - last_behind_warning_).toSec() >= kBehindWarningPeriod)) {
        ROS_WARN("thin_ice_sim: falling behind: real-time factor %.3g of the %.3g asked for", achieved_rtf_,
                 settings_.real_time_factor);
        last_behind_warning_ = after;
      }
    }
    if (settings_.real_time_factor > 0.0) {
      const double due = (sim_->time() - pace_sim_start) / settings_.real_time_factor;
      const double ahead = due - (after - pace_start).toSec();
      if (ahead > 0.0) {
        ros::WallDuration(ahead).sleep();
      } else if (ahead < -0.5) {  // far behind: do not try to catch up in a burst
        pace_start = after;
        pace_sim_start = sim_->time();
      }
    }
  }
}

}  // namespace thin_ice
