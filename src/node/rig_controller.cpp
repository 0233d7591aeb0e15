// rig_controller: an example of the controller a test-rig stack puts around the simulator. It
// listens to the structure load and commands the pusher so that the (smoothed) horizontal load
// stays near a set point, like a load-controlled rig.
//   subscribes structure/wrench (geometry_msgs/WrenchStamped), publishes pusher/cmd_vel (Twist)
//   ~set_point [N] (default 150, as launch/rig_example.launch), ~set_point_rate [N per s of
//   simulated time] (default 0; rig_example.launch's breaking:=true gives 100: a load ramp that
//   fails the sheet) up to ~max_set_point [N] (default 2000), ~proportional_gain [m/s per N] (default 2e-4),
//   ~integral_gain [m/s per N s] (default 4e-4), ~time_constant [s of simulated time] of the
//   load filter (default 0.05), ~max_speed and ~min_speed [m/s] (defaults 0.2 and -0.05: the
//   rig may back off slowly, which a jammed sheet needs to shed load); the set point and the two
//   gains also through dynamic_reconfigure (cfg/RigController.cfg)
// The law, a PI controller on the low-passed load e = F_set - F_filtered, at each load sample:
//   I = clamp(I + k_i e dt, min_speed, max_speed),  v = clamp(I + k_p e, min_speed, max_speed).
#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "thin_ice_sim/RigControllerConfig.h"

namespace {

class RigController {
 public:
  RigController(ros::NodeHandle nh, ros::NodeHandle pnh) {
    pnh.param("set_point", set_point_, set_point_);
    pnh.param("set_point_rate", set_point_rate_, set_point_rate_);
    pnh.param("max_set_point", max_set_point_, max_set_point_);
    pnh.param("proportional_gain", proportional_gain_, proportional_gain_);
    pnh.param("integral_gain", integral_gain_, integral_gain_);
    pnh.param("time_constant", time_constant_, time_constant_);
    pnh.param("max_speed", max_speed_, max_speed_);
    pnh.param("min_speed", min_speed_, min_speed_);
    pnh.param("initial_speed", integral_, integral_);
    command_pub_ = nh.advertise<geometry_msgs::Twist>("pusher/cmd_vel", 10);
    load_sub_ = nh.subscribe("structure/wrench", 50, &RigController::onLoad, this);
    ROS_INFO("rig_controller: holding the horizontal load near %.1f N%s", set_point_,
             set_point_rate_ > 0.0 ? ", ramped up (~set_point_rate)" : "");
    // The set point and the gains change at run time (dynamic_reconfigure), from the values above.
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<thin_ice_sim::RigControllerConfig>>(reconfigure_mutex_, pnh);
    thin_ice_sim::RigControllerConfig now;
    now.set_point = set_point_;
    now.proportional_gain = proportional_gain_;
    now.integral_gain = integral_gain_;
    reconfigure_->updateConfig(now);
    reconfigure_->setCallback([this](thin_ice_sim::RigControllerConfig& c, uint32_t) {
      set_point_ = c.set_point;
      proportional_gain_ = c.proportional_gain;
      integral_gain_ = c.integral_gain;
      ROS_INFO("rig_controller: set point %.1f N, k_p %.3g m/s per N, k_i %.3g m/s per N s", set_point_,
               proportional_gain_, integral_gain_);
    });
  }

 private:
  void onLoad(const geometry_msgs::WrenchStamped& wrench) {
    const double load = wrench.wrench.force.x;
    const double t = wrench.header.stamp.toSec();
    if (!std::isfinite(load)) return;
    const double dt = have_sample_ ? std::max(0.0, t - last_time_) : 0.0;
    last_time_ = t;
    if (!have_sample_) {
      filtered_ = load;
      have_sample_ = true;
    } else if (dt > 0.0) {
      // A load ramp: the set point rises at set_point_rate until max_set_point.
      if (set_point_rate_ > 0.0) set_point_ = std::min(max_set_point_, set_point_ + set_point_rate_ * dt);
      filtered_ += (load - filtered_) * std::min(1.0, dt / time_constant_);  // first-order low-pass
      const double error = set_point_ - filtered_;
      integral_ = std::clamp(integral_ + integral_gain_ * error * dt, min_speed_, max_speed_);
    }
    geometry_msgs::Twist command;
    command.linear.x = std::clamp(integral_ + proportional_gain_ * (set_point_ - filtered_), min_speed_, max_speed_);
    command_pub_.publish(command);
  }

  double set_point_ = 150.0;          // [N] the one default, launch/rig_example.launch's too
  double set_point_rate_ = 0.0;       // [N/s of simulated time] load ramp; 0 = hold
  double max_set_point_ = 2000.0;     // [N] where the ramp stops
  double proportional_gain_ = 2e-4;   // [m/s per N]
  double integral_gain_ = 4e-4;       // [m/s per N s]
  double time_constant_ = 0.05;       // [s]
  double max_speed_ = 0.2;            // [m/s]
  double min_speed_ = -0.05;          // [m/s]
  double integral_ = 0.1;             // [m/s] integral part of the command
  double filtered_ = 0.0;        // [N]
  double last_time_ = 0.0;       // [s]
  bool have_sample_ = false;
  ros::Publisher command_pub_;
  ros::Subscriber load_sub_;
  boost::recursive_mutex reconfigure_mutex_;  // the server's, given to it (see sim_node.hpp)
  std::unique_ptr<dynamic_reconfigure::Server<thin_ice_sim::RigControllerConfig>> reconfigure_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "rig_controller");
  RigController controller{ros::NodeHandle(), ros::NodeHandle("~")};
  ros::spin();
  return 0;
}
