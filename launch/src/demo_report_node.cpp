// demo_report: prints the main demo's report and exits (0 when every step answered).
#include <fstream>
#include <iostream>
#include <sstream>

#include <ros/ros.h>
#include <std_msgs/String.h>

#include "demo_report.h"
#include "spott_ros/parameter_reader.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_report");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string report_file;    // optional copy of the report (./spott demo prints it after shutdown)
  std::string report_json;    // optional JSON report (./spott run)
  std::string scenario;       // the scenario file the run came from, for the JSON report
  std::string missions_file;  // a scenario file whose missions replace goals and tasks
  const auto options = spott_ros::ReadNodeParameters<spott_launch::DemoOptions>(
      pnh, "demo_report", [&](spott_ros::ParameterReader& r, spott_launch::DemoOptions& o) {
        r.Get("world_file", o.world_file);
        r.Get("report_file", report_file);
        r.Get("report_json", report_json);
        r.Get("scenario", scenario);
        r.Get("doors_to_close", o.doors_to_close);
        r.Get("running", o.running);
        r.Get("goals", o.goals);
        r.Get("tasks", o.tasks);
        r.Get("missions_file", missions_file);
        r.Get("timeout_s", o.timeout_s, "s");
        r.Get("leg_timeout_s", o.leg_timeout_s, "s");
        r.Get("goal_tolerance_m", o.goal_tolerance_m, "m");
        r.Get("wait_for_recorder", o.wait_for_recorder);
        r.Get("estimate_from_tf", o.estimate_from_tf);
        if (o.world_file.empty()) r.Fail("world_file is required");
        r.Require(o.timeout_s > 0, "timeout_s", "> 0", o.timeout_s);
        r.Require(o.leg_timeout_s > 0, "leg_timeout_s", "> 0", o.leg_timeout_s);
        r.Require(o.goal_tolerance_m > 0, "goal_tolerance_m", "> 0", o.goal_tolerance_m);
      });
  if (!options) return 1;
  spott_launch::DemoOptions o = *options;
  // The scenario's text, latched: a recorded run carries what it was asked to do, and
  // bag_report judges it from the bag alone as this run does.
  ros::Publisher scenario_pub = pnh.advertise<std_msgs::String>("scenario", 1, true);
  if (!scenario.empty()) {
    std::ifstream in(scenario);
    std::stringstream text;
    text << in.rdbuf();
    std_msgs::String msg;
    msg.data = text.str();
    if (in) scenario_pub.publish(msg);
  }
  if (!missions_file.empty()) {  // a scenario's missions, read as scenario_tool checked them
    std::ifstream in(missions_file);
    std::stringstream text;
    text << in.rdbuf();
    const auto parsed = spott_launch::ParseScenario(text.str(), missions_file);
    if (!in || !parsed.ok()) {
      ROS_FATAL("demo_report: ~missions_file: %s",
                in ? spott_map::FormatErrors(parsed.errors).c_str() : "cannot read the file");
      return 1;
    }
    o.missions = parsed.scenario->missions;
  }
  const spott_launch::DemoReport report = spott_launch::RunDemo(nh, o);
  const std::string text = spott_launch::FormatReport(report);
  std::cout << text << std::flush;
  if (!report_file.empty()) {
    std::ofstream out(report_file);
    out << text;
    if (!out) ROS_ERROR("demo_report: cannot write ~report_file '%s'", report_file.c_str());
  }
  if (!report_json.empty()) {
    std::ofstream out(report_json);
    out << spott_launch::FormatReportJson(report, scenario);
    if (!out) ROS_ERROR("demo_report: cannot write ~report_json '%s'", report_json.c_str());
  }
  return report.ok ? 0 : 1;
}
