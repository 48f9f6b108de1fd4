// Projection of the global goal onto the border of the local planner's window (SPOTT III.D.2,
// Fig. 14). With p_g the goal, p_r the robot, n_r and n_g their nodes, b_pf the window and the
// global path <n_r, e_i, n_j, ..., n_g>:
//   1. p_g within b_pf and n_g = n_r: nothing to do, the local planner descends to p_g.
//   2. p_g within n_r but not within b_pf: the goal is the portion of the side of b_pf that is
//      contained in n_r (the side the straight line p_r -> p_g leaves the window by).
//   3. otherwise: e_k is the first edge of the path not completely within b_pf, n_k the node
//      traversed just before it, p_k the intersection of b_pf's border with the line joining
//      the centre of e_k and the centre of n_k; the goal is the portion of the side of b_pf
//      through p_k that lies in n_k and holds p_k.
// When p_g is within b_pf in another node and every edge of the path is within b_pf, the goal
// itself is used (case 4 of spott_msgs/ProjectedGoal). "n_g = n_r" means a path without doors: a
// path that leaves n_r and comes back into it (an obstacle inside n_r separates robot and goal)
// is the general case.
//
// The paper leaves some geometry open; the rules used there are reported in `rule`:
//   - "the line" is the infinite line through centre(n_k) and centre(e_k); of its two
//     crossings with the border p_k is the one reached last moving towards e_k (where the robot
//     leaves the window on its way to the door), also when the window lies behind centre(n_k);
//   - the edge's centre is inside the window (only one end of its opening is outside) and
//     centre(n_k) is not: p_k is where the line enters the window, on n_k's side;
//   - both centres are inside the window: the line is extended past the edge's centre;
//   - the line misses the window: the line from the robot to the edge's centre is used;
//   - p_k is a window corner: of the two sides, the one with the longer portion in n_k;
//   - the side through p_k has no portion in n_k holding p_k: the portion of n_k on the border
//     nearest p_k; none at all: the single point p_k;
//   - p_g outside b_pf in another node but every edge within b_pf: case 3 with the goal in the
//     place of e_k (the line from centre(n_g) to p_g, node n_g).
#pragma once

#include <string>

#include "spott_global_planner/border_geometry.h"
#include "spott_global_planner/global_planner.h"

namespace spott_global_planner {

/// The numbers of spott_msgs/ProjectedGoal.
enum class ProjectionCase {
  kSameNodeInWindow = 1,       ///< case 1
  kSameNodeOutsideWindow = 2,  ///< case 2
  kGeneral = 3,                ///< case 3
  kGoalInWindow = 4,           ///< goal in window, other node, every path edge in window
};
const char* ToString(ProjectionCase c);

struct ProjectedGoal {
  ProjectionCase projection_case = ProjectionCase::kSameNodeInWindow;
  Vec2 goal{0.0, 0.0};     ///< p_g (m, map frame)
  bool on_border = false;  ///< true: the goal is `border`; false: the point `goal`
  Segment border;          ///< the border segment (the thick line of Fig. 14), when on_border
  WindowSide side = WindowSide::kBottom;  ///< the window side `border` lies on
  /// Case 3: p_k. Case 2: where the line p_r -> p_g leaves the window.
  Vec2 projected_point{0.0, 0.0};
  int edge = -1;        ///< e_k (door index), case 3
  std::string edge_id;  ///< e_k, case 3 (empty when the goal stood in for it)
  int node = -1;        ///< n_k (case 3) or n_r (case 2), room index
  std::string node_id;
  Box window;        ///< b_pf
  std::string rule;  ///< which of the rules above decided the geometry ("" = the paper's)
};

/// Projects `goal` for the local planner's `window` along `path` (which must start in the
/// robot's node and end in the goal's). `robot` is p_r (m). When no portion of the node on the
/// border holds the crossing, the nearest portion at least `min_portion_m` long is taken (the
/// robot's padded diameter: a shorter strip at a window corner is all padding), the nearest of
/// any length only when none is that long.
ProjectedGoal ProjectGoalOntoWindow(const PlanningGraph& graph, const GlobalPath& path,
                                    const Vec2& robot, const Vec2& goal, const Box& window,
                                    double min_portion_m = 0.0);

/// True when both ends of the door's opening lie within the window (border included).
bool EdgeWithinWindow(const spott_map::Door& door, const Box& window);

}  // namespace spott_global_planner
