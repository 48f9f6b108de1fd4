// tr_live_render OUT.png [TOPIC]: waits for one live TR tree (std_msgs/String DOT, default
// /tr_plus_node/tree_dot), renders it with Graphviz (true conditions shaded, firing arc red) and
// exits. The DOT text holds one digraph per active program; each is written as OUT_<k>.<ext>.
#include <ros/ros.h>
#include <std_msgs/String.h>

#include "../src/render/dot_render.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "tr_live_render", ros::init_options::AnonymousName);
  if (argc < 2) {
    std::cerr << "usage: tr_live_render OUT.png [TOPIC]\n";
    return 2;
  }
  const std::string out = argv[1];
  const std::string topic = argc > 2 ? argv[2] : "/tr_plus_node/tree_dot";
  ros::NodeHandle nh;
  auto msg = ros::topic::waitForMessage<std_msgs::String>(topic, nh, ros::Duration(30));
  if (!msg) {
    ROS_ERROR("tr_live_render: no message on %s", topic.c_str());
    return 1;
  }
  const size_t dot = out.rfind('.');
  const std::string base = dot == std::string::npos ? out : out.substr(0, dot);
  const std::string ext = dot == std::string::npos ? "png" : out.substr(dot + 1);
  size_t start = 0;
  int k = 0;
  int errors = 0;
  while (true) {
    const size_t next = msg->data.find("digraph", start + 1);
    const std::string one =
        msg->data.substr(start, next == std::string::npos ? std::string::npos : next - start);
    const std::string path = k == 0 ? out : base + "_" + std::to_string(k) + "." + ext;
    const std::string error = spott_tr_plus::RenderDot(one, ext, path);
    if (!error.empty()) {
      ROS_ERROR("tr_live_render: %s", error.c_str());
      ++errors;
    } else {
      ROS_INFO("tr_live_render: wrote %s", path.c_str());
    }
    ++k;
    if (next == std::string::npos) break;
    start = next;
  }
  return errors ? 1 : 0;
}
