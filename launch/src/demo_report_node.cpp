// demo_report: prints the main demo's report and exits (0 when every step answered).
#include <fstream>
#include <iostream>

#include <ros/ros.h>

#include "demo_report.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_report");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  spott_launch::DemoOptions options;
  if (!pnh.getParam("world_file", options.world_file)) {
    ROS_FATAL("demo_report: ~world_file is required");
    return 1;
  }
  pnh.getParam("doors_to_close", options.doors_to_close);
  pnh.getParam("running", options.running);
  pnh.getParam("goals", options.goals);
  pnh.param("timeout", options.timeout_s, options.timeout_s);
  pnh.param("leg_timeout", options.leg_timeout_s, options.leg_timeout_s);
  if (!(options.timeout_s > 0.0) || !(options.leg_timeout_s > 0.0)) {
    ROS_FATAL("demo_report: ~timeout and ~leg_timeout must be > 0 s");
    return 1;
  }
  std::string report_file;  // optional copy of the report (./spott demo prints it after shutdown)
  pnh.param("report_file", report_file, report_file);
  const spott_launch::DemoReport report = spott_launch::RunDemo(nh, options);
  const std::string text = spott_launch::FormatReport(report);
  std::cout << text << std::flush;
  if (!report_file.empty()) {
    std::ofstream out(report_file);
    out << text;
    if (!out) ROS_ERROR("demo_report: cannot write ~report_file '%s'", report_file.c_str());
  }
  return report.ok ? 0 : 1;
}
