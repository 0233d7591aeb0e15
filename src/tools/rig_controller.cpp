// rig_controller: an example of the controller a test-rig stack puts around the simulator. It
// listens to the structure load and commands the pusher so that the (smoothed) horizontal load
// stays near a set point, like a load-controlled rig.
//   subscribes structure/wrench (geometry_msgs/WrenchStamped), publishes pusher/cmd_vel (Twist)
//   ~set_point [N] (default 300), ~gain [m/s per N] (default 2e-4), ~time_constant [s of
//   simulated time] for the load filter (default 0.2), ~max_speed [m/s] (default 0.2),
//   ~min_speed [m/s] (default 0: the rig never pulls back)
// The law: v = clamp(v + gain * (F_set - F_filtered) * dt_filter, min_speed, max_speed), an
// integral controller on the low-passed load, updated at each load sample.
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>

namespace {

class RigController {
 public:
  RigController(ros::NodeHandle nh, ros::NodeHandle pnh) {
    pnh.param("set_point", set_point_, set_point_);
    pnh.param("gain", gain_, gain_);
    pnh.param("time_constant", time_constant_, time_constant_);
    pnh.param("max_speed", max_speed_, max_speed_);
    pnh.param("min_speed", min_speed_, min_speed_);
    pnh.param("initial_speed", speed_, speed_);
    command_pub_ = nh.advertise<geometry_msgs::Twist>("pusher/cmd_vel", 10);
    load_sub_ = nh.subscribe("structure/wrench", 50, &RigController::onLoad, this);
    ROS_INFO("rig_controller: holding the horizontal load near %.1f N", set_point_);
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
      filtered_ += (load - filtered_) * std::min(1.0, dt / time_constant_);  // first-order low-pass
      speed_ = std::clamp(speed_ + gain_ * (set_point_ - filtered_) * dt, min_speed_, max_speed_);
    }
    geometry_msgs::Twist command;
    command.linear.x = speed_;
    command_pub_.publish(command);
  }

  double set_point_ = 300.0;     // [N]
  double gain_ = 2e-4;           // [m/s per N s]
  double time_constant_ = 0.2;   // [s]
  double max_speed_ = 0.2;       // [m/s]
  double min_speed_ = 0.0;       // [m/s]
  double speed_ = 0.1;           // [m/s] commanded now
  double filtered_ = 0.0;        // [N]
  double last_time_ = 0.0;       // [s]
  bool have_sample_ = false;
  ros::Publisher command_pub_;
  ros::Subscriber load_sub_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "rig_controller");
  RigController controller{ros::NodeHandle(), ros::NodeHandle("~")};
  ros::spin();
  return 0;
}
