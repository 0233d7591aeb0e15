// thin_ice_node: the Thin Ice Model simulator as a ROS node (see README, "ROS interface").
#include <ros/ros.h>

#include <cstdio>
#include <exception>

#include <xmlrpcpp/XmlRpcException.h>

#include "sim_node.hpp"
#include "thin_ice_sim/built_backends.hpp"
#include "thin_ice_sim/openmp_wait_policy.hpp"

int main(int argc, char** argv) {
  thin_ice::restartWithPassiveOpenMpWaitUnlessSet(argv);
  thin_ice::registerBuiltBackends();
  ros::init(argc, argv, "thin_ice_sim");
  try {
    thin_ice::SimNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    node.run();
  } catch (const std::exception& e) {
    ROS_FATAL("thin_ice_sim: %s", e.what());
    // rosconsole may not flush before a quick exit: say it on stderr too.
    std::fprintf(stderr, "[FATAL] thin_ice_sim: %s\n", e.what());
    return 1;
  } catch (const XmlRpc::XmlRpcException& e) {  // not a std::exception
    ROS_FATAL("thin_ice_sim: parameter server value of an unexpected type: %s", e.getMessage().c_str());
    std::fprintf(stderr, "[FATAL] thin_ice_sim: parameter server value of an unexpected type: %s\n",
                 e.getMessage().c_str());
    return 1;
  }
  return 0;
}
