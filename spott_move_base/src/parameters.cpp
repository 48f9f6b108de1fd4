#include "spott_move_base/parameters.h"

namespace spott_move_base {

void Read(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("navigate_action", p.navigate_action);
  r.Get("server_timeout_s", p.server_timeout_s, "s");
  r.Require(p.server_timeout_s > 0, "server_timeout_s", "> 0", p.server_timeout_s);
  if (p.navigate_action.empty()) r.Fail("navigate_action must not be empty");
}

}  // namespace spott_move_base
