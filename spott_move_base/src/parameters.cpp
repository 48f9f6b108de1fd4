#include "spott_move_base/parameters.h"

namespace spott_move_base {

void Read(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("navigate_action", p.navigate_action);
  r.Get("server_timeout_s", p.server_timeout_s, "s");
  // waitForServer takes it as a ros::Duration (at most 2^31 s); an hour is plenty.
  r.Require(p.server_timeout_s > 0 && p.server_timeout_s <= 3600, "server_timeout_s",
            "in (0, 3600]", p.server_timeout_s);
  if (p.navigate_action.empty()) r.Fail("navigate_action must not be empty");
}

}  // namespace spott_move_base
