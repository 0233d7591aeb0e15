// The thin_ice_sim ROS node: owns a Simulation and connects it to a test-rig stack, as Gazebo's
// ROS interface does for a rigid-body world. Single-threaded: callbacks run between steps, so the
// simulation is never touched from two threads.
#pragma once

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <string>
#include <vector>

#include "thin_ice_sim/SimConfig.h"
#include "thin_ice_sim/Step.h"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

/// Node parameters (private namespace ~), read once at start-up.
struct NodeSettings {
  std::string scenario;                 ///< ~scenario: a name in config/scenarios or a path
  std::vector<std::string> overrides;   ///< ~set: "section.key=value" items
  std::string backend = "cpu";          ///< ~backend: cpu | cuda | auto
  double real_time_factor = 1.0;        ///< ~real_time_factor: target pacing; 0 = as fast as possible
  double load_rate = 100.0;             ///< ~load_rate [Hz of simulated time]
  double marker_rate = 10.0;            ///< ~marker_rate [Hz of wall time]
  double status_rate = 10.0;            ///< ~status_rate [Hz of wall time]
  bool publish_clock = true;            ///< ~publish_clock
  double cmd_timeout = 1.0;             ///< ~cmd_timeout [s simulated]; 0 = commands never expire.
                                        ///< Simulated, so that a command waits out a pause and
                                        ///< sim/step with a controller in the loop keeps it
  double paused_clock_rate = 10.0;      ///< ~paused_clock_rate [Hz wall]: /clock (frozen) while paused
  double load_arrow_scale = 0.003;      ///< ~load_arrow_scale [m per N/m of structure width]: the
                                        ///< length of the load arrow in ice/cells; 0 = none
  double max_pusher_speed = 0.5;        ///< ~max_pusher_speed [m/s]; the scenario's pusher.velocity too
  long max_steps_per_call = 100000;     ///< ~max_steps_per_call: sim/step refuses a longer request
  bool start_paused = false;            ///< ~paused
  double stop_time = 0.0;               ///< ~stop_time [s simulated]: shut down on reaching it; 0 = never
  std::string world_frame = "world";    ///< ~world_frame
  std::string structure_frame = "structure";  ///< ~structure_frame
  std::string pusher_frame = "pusher";  ///< ~pusher_frame
};

/// What readNodeSettings allows. The bounds keep every period and count the node derives from a
/// parameter finite and representable (a WallDuration of 1/rate, a step count of span/dt) and keep
/// one call from blocking the single-threaded node for hours; they are far outside any rig's use.
struct NodeLimits {
  double min_real_time_factor = 1e-3, max_real_time_factor = 1e6;  ///< [-] (0 also allowed)
  double min_load_rate = 1.0, max_load_rate = 1e5;        ///< [Hz of simulated time]
  double min_wall_rate = 0.01, max_wall_rate = 1e3;       ///< [Hz of wall time] markers, status,
                                                          ///< the paused /clock
  double min_cmd_timeout = 1e-3, max_cmd_timeout = 1e6;   ///< [s simulated] (0 also allowed)
  double min_pusher_speed = 1e-6, max_pusher_speed = 10.0;  ///< [m/s] ~max_pusher_speed; the health
                                                            ///< check stops any cell at 50 m/s
  double max_steps_per_call = 1e8;                        ///< [-] upper bound of ~max_steps_per_call
  double min_stop_time = 0.0, max_stop_time = 1e9;        ///< [s simulated]
  double min_load_arrow_scale = 1e-6, max_load_arrow_scale = 1.0;  ///< [m per N/m] (0 also allowed)
};
inline constexpr NodeLimits kNodeLimits{};

/// Reads and checks the settings; throws std::invalid_argument naming the parameter.
NodeSettings readNodeSettings(const ros::NodeHandle& private_nh);

class SimNode {
 public:
  /// Loads the scenario and builds the simulation; throws (ScenarioError, std::runtime_error)
  /// with a message naming the file and key when it cannot.
  SimNode(ros::NodeHandle nh, ros::NodeHandle private_nh);
  /// Steps, publishes and paces until ROS shuts down.
  void run();

 private:
  void onCommand(const geometry_msgs::Twist& command);
  bool onPause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  /// sim/unpause, std_srvs/Empty as Gazebo's: runs the simulation again; after a numerical blow-up
  /// it stays paused, says why in the log and in sim/status (last_error), and answers all the same.
  bool onUnpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  /// sim/unpause_checked, std_srvs/Trigger: the same, with success = false and the reason.
  bool onUnpauseChecked(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response);
  /// Runs the simulation again unless it blew up; returns "" or why not.
  std::string unpause();
  bool onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool onStep(thin_ice_sim::Step::Request& request, thin_ice_sim::Step::Response& response);

  /// Pusher velocity for the next step: the scenario's until the first command, then the last
  /// command until it is older than cmd_timeout of simulated time, then zero.
  double commandedVelocity();
  /// Advances one load period (or less while paused: nothing) and publishes what is due.
  void advanceAndPublish();
  /// Steps `steps` time steps in load periods, publishing each period's loads, clock and tf as
  /// the running node does (sim/step); stops early on a blow-up.
  void stepPublishingEachPeriod(long steps);
  void publishLoads();
  void publishClockAndTf();
  void publishStatus();
  void publishMarkers();
  void publishStructureTransform();
  /// Checks the simulation after a step: on a blow-up, pause and report.
  void checkHealth();
  /// dynamic_reconfigure: the pacing, the pusher's speed limit, the command timeout and the marker
  /// rate change from the next step; a value outside the start-up checks is refused with a warning
  /// and the old one stays.
  void onReconfigure(thin_ice_sim::SimConfig& config, uint32_t level);

  ros::NodeHandle nh_, private_nh_;
  NodeSettings settings_;
  std::unique_ptr<Simulation> sim_;
  ros::Publisher wrench_pub_, panels_pub_, markers_pub_, status_pub_, clock_pub_;
  ros::Subscriber command_sub_;
  ros::ServiceServer pause_srv_, unpause_srv_, unpause_checked_srv_, reset_srv_, step_srv_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  // The server's own mutex given to it, so that updateConfig from the constructor is safe (without
  // one, dynamic_reconfigure warns of deadlocks at every start).
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<thin_ice_sim::SimConfig>> reconfigure_;

  bool have_command_ = false;
  bool command_expired_ = false;
  bool reported_travel_end_ = false;    ///< the pusher's travel end has been logged (once per arrival)
  double command_velocity_ = 0.0;       ///< [m/s] last accepted command
  double command_sim_time_ = 0.0;       ///< [s simulated] when it arrived
  double applied_velocity_ = 0.0;       ///< [m/s] used in the last step
  double achieved_rtf_ = 0.0;           ///< simulated s per wall s over the last second
  ros::WallTime rtf_window_start_;
  double rtf_window_sim_start_ = 0.0;
  ros::WallTime next_marker_time_, next_status_time_, next_paused_clock_time_;
  ros::WallTime last_behind_warning_;   ///< the "falling behind" warning is throttled on wall time
  bool repace_ = false;                 ///< the real-time factor changed: pacing starts again
  std::string last_error_;
};

}  // namespace thin_ice
