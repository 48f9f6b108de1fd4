// The demo's report as JSON, for scripts and the scenario runner (./spott run).
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "demo_report.h"

namespace spott_launch {

namespace {

using nlohmann::json;

json Leg(const NavigationLeg& leg) {
  json j = {{"goal", leg.goal},
            {"task", leg.task},
            {"interpretation", leg.interpretation},
            {"reached", leg.reached},
            {"outcome", leg.outcome},
            {"navigate_outcome", leg.navigate_outcome},
            {"task_outcome", leg.task_outcome},
            {"global_path", leg.global_path},
            {"recoveries", leg.recoveries},
            {"features_added", leg.features_added},
            {"trace", CompactTrace(leg.trace)},
            {"start_sim_s", leg.start_sim_s},
            {"sim_time_s", leg.sim_time_s},
            {"wall_time_s", leg.wall_time_s},
            {"path_length_m", leg.path_length_m},
            {"final_error_m", leg.final_error_m},
            {"final_position", {leg.final_position.x(), leg.final_position.y()}},
            {"min_wall_distance_m", leg.min_wall_distance_m},
            {"bumper_hits", leg.bumper_hits},
            {"body_contacts", leg.body_contacts},
            {"lost_reports", leg.lost_reports},
            {"lost_onsets_s", leg.lost_onsets_s},
            {"contact_onsets_s", leg.contact_onsets_s}};
  if (leg.has_target) j["target"] = {leg.target.x, leg.target.y, leg.target.yaw};
  if (!leg.found_label.empty()) {
    j["found"] = {{"label", leg.found_label},
                  {"at", {leg.found_at.x(), leg.found_at.y()}},
                  {"nearest_of_kind_m", leg.found_nearest_m}};
  }
  if (!leg.mission.empty()) {
    j["mission"] = leg.mission;
    j["mission_outcome"] = leg.mission_outcome;
    j["monitors_fired"] = leg.monitors_fired;
  }
  // Localization against the ground truth; none when the stack ran on the simulator's pose.
  if (leg.estimates > 0) {
    j["localization"] = {{"estimates", leg.estimates},
                         {"mean_position_error_m", leg.mean_position_error_m},
                         {"max_position_error_m", leg.max_position_error_m},
                         {"mean_heading_error_rad", leg.mean_heading_error_rad},
                         {"max_heading_error_rad", leg.max_heading_error_rad}};
  }
  return j;
}

}  // namespace

std::string FormatReportJson(const DemoReport& r, const std::string& scenario) {
  json j;
  j["scenario"] = scenario;
  j["world"] = r.world;
  j["ok"] = r.ok;
  if (!r.ok) j["failure"] = r.failure;
  j["elapsed_wall_s"] = r.elapsed_s;
  const auto& legs = r.navigation.legs;
  const auto reached =
      std::count_if(legs.begin(), legs.end(), [](const NavigationLeg& l) { return l.reached; });
  int bumper_hits = 0, body_contacts = 0, lost_reports = 0;
  double path_m = 0.0, sim_s = 0.0, min_clearance_m = INFINITY, max_error_m = 0.0;
  for (const auto& l : legs) {
    bumper_hits += l.bumper_hits;
    body_contacts += l.body_contacts;
    lost_reports += l.lost_reports;
    path_m += l.path_length_m;
    sim_s += l.sim_time_s;
    min_clearance_m = std::min(min_clearance_m, l.min_wall_distance_m);
    max_error_m = std::max(max_error_m, l.max_position_error_m);
  }
  // "succeeded": every leg reached on the ground truth with no contact, and every scheduled
  // fault happened (a refused one means the run was not the one the scenario describes).
  const bool faults_applied = std::all_of(r.faults.begin(), r.faults.end(),
                                          [](const DemoReport::Fault& f) { return f.applied; });
  j["outcome"] =
      !r.ok               ? "failed"
      : !r.navigation.ran ? "not run"
      : !faults_applied   ? "fault refused"
      : reached == static_cast<long>(legs.size()) && bumper_hits == 0 && body_contacts == 0
          ? "succeeded"
          : "failed";
  j["legs_reached"] = reached;
  j["legs_total"] = legs.size();
  j["by_task"] = r.navigation.by_task;
  j["by_mission"] = r.navigation.by_mission;
  if (!r.navigation.ran) j["skipped"] = r.navigation.skipped;
  j["totals"] = {{"sim_time_s", sim_s},          {"path_length_m", path_m},
                 {"bumper_hits", bumper_hits},   {"body_contacts", body_contacts},
                 {"lost_reports", lost_reports}, {"max_position_error_m", max_error_m}};
  if (!legs.empty()) j["totals"]["min_wall_distance_m"] = min_clearance_m;
  j["requested_real_time_factor"] = r.navigation.requested_real_time_factor;
  j["legs"] = json::array();
  for (const auto& l : legs) j["legs"].push_back(Leg(l));
  j["faults"] = json::array();
  for (const auto& f : r.faults) {
    json fault = {{"sim_time_s", f.sim_time_s},
                  {"kind", f.kind},
                  {"what", f.what},
                  {"applied", f.applied},
                  {"during_leg", nullptr}};
    // The leg it fell in answers for it (0-based; null: before the legs began or after).
    for (std::size_t i = 0; i < legs.size(); ++i) {
      if (f.sim_time_s >= legs[i].start_sim_s &&
          f.sim_time_s <= legs[i].start_sim_s + legs[i].sim_time_s) {
        fault["during_leg"] = i;
      }
    }
    j["faults"].push_back(fault);
  }
  j["reachability"] = {
      {"start_room", r.start_room}, {"reachable", r.reachable}, {"unreachable", r.unreachable}};
  return j.dump(2) + "\n";
}

}  // namespace spott_launch
