// fig18_run: one case of the Fig. 18 campaign (fig18_campaign.h).
//   fig18_run --case SEED WORLD_FILE   prints the case's start pose "x y yaw" (no ROS), for
//                                      robot_sim's start_pose;
//   as a node (fig18.launch): ~seed, ~world_file, ~timeout_s, ~tolerance_m, ~result_file: runs
//   the case against the running stack, appends its line to ~result_file, exits 0 on arrival.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>

#include <ros/ros.h>

#include "fig18_campaign.h"
#include "spott_map/world_loader.h"
#include "spott_ros/parameter_reader.h"

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--case") == 0) {
    const auto loaded = spott_map::LoadWorldFile(argv[3]);
    if (!loaded.ok()) {
      std::cerr << spott_map::FormatErrors(loaded.errors);
      return 1;
    }
    const auto c = spott_launch::Fig18CaseFor(*loaded.world, std::atoi(argv[2]));
    std::printf("%.3f %.3f %.3f\n", c.start.x, c.start.y, c.start.yaw);
    return c.command.empty() ? 1 : 0;
  }
  ros::init(argc, argv, "fig18_run");
  ros::NodeHandle nh, pnh("~");
  struct Options {
    int seed = 1;
    std::string world_file, result_file;
    double timeout_s = 300.0, tolerance_m = 0.35;
  };
  const auto o = spott_ros::ReadNodeParameters<Options>(
      pnh, "fig18_run", [](spott_ros::ParameterReader& r, Options& p) {
        r.Get("seed", p.seed);
        r.Get("world_file", p.world_file);
        r.Get("result_file", p.result_file);
        r.Get("timeout_s", p.timeout_s, "s");
        r.Get("tolerance_m", p.tolerance_m, "m");
        if (p.world_file.empty()) r.Fail("world_file is required");
        r.Require(p.timeout_s > 0, "timeout_s", "> 0", p.timeout_s);
        r.Require(p.tolerance_m > 0, "tolerance_m", "> 0", p.tolerance_m);
      });
  if (!o) return 1;
  const auto loaded = spott_map::LoadWorldFile(o->world_file);
  if (!loaded.ok()) {
    ROS_FATAL("fig18_run: %s", spott_map::FormatErrors(loaded.errors).c_str());
    return 1;
  }
  const auto c = spott_launch::Fig18CaseFor(*loaded.world, o->seed);
  ROS_INFO("fig18_run: seed %d: %s -> %s: %s", c.seed, c.start_room.c_str(), c.goal_room.c_str(),
           c.command.c_str());
  const auto run = spott_launch::RunFig18Case(nh, c, o->timeout_s, o->tolerance_m);
  const std::string line = spott_launch::Fig18Line(run);
  std::cout << "fig18: " << line << std::endl;
  if (!o->result_file.empty()) std::ofstream(o->result_file, std::ios::app) << line << "\n";
  return run.arrived ? 0 : 1;
}
