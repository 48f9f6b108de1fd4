// demo_report: prints the main demo's report and exits (0 when every step answered).
#include <fstream>
#include <iostream>

#include <ros/ros.h>

#include "demo_report.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_report");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string world_file;
  std::vector<std::string> doors;
  double timeout_s = 30.0;
  if (!pnh.getParam("world_file", world_file)) {
    ROS_FATAL("demo_report: ~world_file is required");
    return 1;
  }
  pnh.getParam("doors_to_close", doors);
  pnh.param("timeout", timeout_s, timeout_s);
  std::string report_file;  // optional copy of the report (./spott demo prints it after shutdown)
  pnh.param("report_file", report_file, report_file);
  const spott_launch::DemoReport report = spott_launch::RunDemo(nh, world_file, doors, timeout_s);
  const std::string text = spott_launch::FormatReport(report);
  std::cout << text << std::flush;
  if (!report_file.empty()) {
    std::ofstream out(report_file);
    out << text;
    if (!out) ROS_ERROR("demo_report: cannot write ~report_file '%s'", report_file.c_str());
  }
  return report.ok ? 0 : 1;
}
