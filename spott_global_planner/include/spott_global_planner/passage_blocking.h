// Which passages through a node are blocked (SPOTT III: the global planner replans when "the
// path from one access way to another (e.g., door) is blocked by a newly discovered obstacle").
// The node's outline is rasterized, the obstacles that meet it are drawn padded by the robot's
// radius plus the largest localization error (the padding the local planner uses, footnote 15),
// and the free cells are split into 4-connected components. A door reaches the components of
// the free cells just inside its opening; two doors are joined when they reach a common
// component. A door that reaches none (an obstacle in front of it, or an opening narrower than
// twice the padding) is joined to no other door.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spott_global_planner/planning_graph.h"
#include "spott_map/map_feature.h"
#include "spott_map/world.h"

namespace spott_global_planner {

struct PassageParameters {
  double resolution_m = 0.05;  ///< Cell side of the node's raster (m), > 0.
  double padding_m = 0.325;    ///< Robot radius + largest localization error (m), >= 0.
  /// Free cells whose centre lies within this distance of a door's opening, inside the node,
  /// are where the door is reached from (m), > 0; a few cells.
  double door_depth_m = 0.15;
  /// A node's raster is refused (all its passages are taken as free) above this many cells.
  int max_cells = 4000000;
};

std::vector<std::string> ValidateParameters(const PassageParameters& p);

struct PassageAnalysis {
  /// Pairs (i, j), i < j, of indices into the `doors` argument that no free way joins.
  std::vector<std::pair<int, int>> blocked;
  /// Per door: false when no free cell lies just inside its opening.
  std::vector<bool> door_reachable;
  /// False when the node was too large to rasterize (nothing is reported blocked then).
  bool analysed = true;
  /// The raster: free cells carry the index of their 4-connected component, others -1.
  spott_map::Vec2 origin{0.0, 0.0};
  double resolution = 0.0;
  int width = 0;
  int height = 0;
  std::vector<int> labels;
  /// Per door: the components the free cells just inside its opening belong to (sorted).
  std::vector<std::vector<int>> door_components;
};

/// The components of the free cells within `radius` (m) of `p` (the cell holding `p` alone when
/// it is free): where the robot or the goal stands. Sorted; empty when nothing free is near.
std::vector<int> ComponentsNear(const PassageAnalysis& analysis, const spott_map::Vec2& p,
                                double radius);

/// Indices (into the analysed doors) of the doors that share a component with `components`.
std::vector<int> DoorsReachedFrom(const PassageAnalysis& analysis,
                                  const std::vector<int>& components);

/// Analyses one node: `doors` are the node's doors (any state), `obstacles` every feature that
/// may meet it (walls included: the node's own walls only narrow its border).
PassageAnalysis AnalysePassages(const spott_map::Room& room,
                                const std::vector<const spott_map::Door*>& doors,
                                const std::vector<const spott_map::MapFeature*>& obstacles,
                                const PassageParameters& params);

/// Keeps a graph's blocked passages in step with the map's features: a node is analysed again
/// only when the features that meet it (by id and geometry) or its doors' openings changed.
class PassageMonitor {
 public:
  /// Throws std::invalid_argument listing every violation.
  explicit PassageMonitor(const PassageParameters& params);

  /// Re-analyses the nodes of `graph` whose features changed and sets their blocked passages.
  /// Returns the indices of the nodes whose set of blocked passages changed.
  std::vector<int> Update(PlanningGraph& graph, const std::vector<spott_map::MapFeature>& features);
  /// Forget what was analysed (call after replacing the graph).
  void Reset() {
    signature_.clear();
    kept_.clear();
  }

  /// For a node with blocked passages: the doors (graph indices) reached from `p` inside it,
  /// i.e. on p's side of the obstacles (free cells within the padding of `p` count, since the
  /// robot stands closer than that to an obstacle it has just found). nullopt for a node
  /// without blocked passages (every door is reached).
  std::optional<std::vector<int>> DoorsReachedFrom(int room, const spott_map::Vec2& p) const;
  /// False when obstacles inside node `room` separate `p` from `q`.
  bool SameSide(int room, const spott_map::Vec2& p, const spott_map::Vec2& q) const;

 private:
  struct Kept {
    std::vector<int> doors;  // graph indices, in the order analysed
    PassageAnalysis analysis;
  };
  double Radius() const { return params_.padding_m + params_.resolution_m; }

  PassageParameters params_;
  std::vector<std::string> signature_;  // per room: what the last analysis saw
  std::map<int, Kept> kept_;            // analyses of the nodes with blocked passages
};

}  // namespace spott_global_planner
