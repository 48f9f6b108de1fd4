// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of markov_localization_parameters_fuzz.
#include <gtest/gtest.h>

#include "markov_localization/ros/parameters.h"
#include "markov_localization/ros/sensed_map_parameters.h"

namespace markov_localization {
namespace {

// Whether one of the reader's errors names `text`.
bool Names(const std::vector<std::string>& errors, const std::string& text) {
  for (const auto& e : errors)
    if (e.find(text) != std::string::npos) return true;
  return false;
}

std::vector<std::string> Read(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  ReadParameters(r, *p);
  return r.Finish();
}

TEST(Parameters, TheShippedDefaultsAreAccepted) {
  NodeParameters p;
  EXPECT_TRUE(Read(XmlRpc::XmlRpcValue(), &p).empty());
}

// Found by markov_localization_parameters_fuzz: map/resolution_m 1e-300 was accepted, and the
// map model counts a building's cells in an int (undefined far beyond it).
TEST(Parameters, AMapCellTooFineForAnyBuildingIsRefused) {
  for (double res : {1e-300, 1e-6, 0.009}) {
    XmlRpc::XmlRpcValue v;
    v["map"]["resolution_m"] = res;
    NodeParameters p;
    const auto errors = Read(v, &p);
    ASSERT_EQ(errors.size(), 1u) << res;
    EXPECT_NE(errors[0].find("~map/resolution_m"), std::string::npos) << errors[0];
  }
  XmlRpc::XmlRpcValue v;
  v["map"]["resolution_m"] = 0.01;
  NodeParameters p;
  EXPECT_TRUE(Read(v, &p).empty());
  EXPECT_EQ(p.map.resolution_m, 0.01);
}

std::vector<std::string> ReadSensed(const XmlRpc::XmlRpcValue& values, SensedMapNodeParameters* p) {
  spott_ros::ParameterReader r(values);
  ReadParameters(r, *p);
  return r.Finish();
}

TEST(SensedMapParameters, DefaultsAreAcceptedAndBadValuesRefusedByName) {
  SensedMapNodeParameters p;
  EXPECT_TRUE(ReadSensed(XmlRpc::XmlRpcValue(), &p).empty());
  XmlRpc::XmlRpcValue v;
  v["period_s"] = 0.0;
  v["max_correction_deg"] = 1e308;  // infinite in radians
  v["initial_pose"] = std::string("1 nan 0");
  v["odom_frame"] = std::string("map");
  v["gate"] = 0.3;  // misspelt gate_m
  const auto errors = ReadSensed(v, &p);
  ASSERT_EQ(errors.size(), 5u);
  EXPECT_TRUE(Names(errors, "~period_s must be > 0"));
  EXPECT_TRUE(Names(errors, "~max_correction_deg must be finite"));
  EXPECT_TRUE(Names(errors, "~initial_pose"));
  EXPECT_TRUE(Names(errors, "~odom_frame must differ from ~map_frame"));
  EXPECT_TRUE(Names(errors, "~gate"));
}

TEST(SensedMapParameters, TheStartAndTheTrackersValuesArrive) {
  XmlRpc::XmlRpcValue v;
  v["initial_pose"] = std::string("12 11 0.5");
  v["period_s"] = 5;
  v["max_incidence_deg"] = 6.0;
  SensedMapNodeParameters p;
  ASSERT_TRUE(ReadSensed(v, &p).empty());
  ASSERT_TRUE(p.initial_pose.has_value());
  EXPECT_DOUBLE_EQ(p.initial_pose->yaw, 0.5);
  EXPECT_DOUBLE_EQ(p.tracker.period_s, 5.0);
  EXPECT_NEAR(p.tracker.max_incidence_rad, 6.0 * M_PI / 180.0, 1e-12);
}

TEST(SensedMapParameters, TheWallLatticesValuesArriveAndBadOnesAreNamed) {
  XmlRpc::XmlRpcValue v;
  v["wall_lattice"]["enabled"] = false;
  v["wall_lattice"]["gate_deg"] = 3.0;
  v["wall_lattice"]["min_points"] = 20;
  SensedMapNodeParameters p;
  ASSERT_TRUE(ReadSensed(v, &p).empty());
  EXPECT_FALSE(p.tracker.wall_lattice.enabled);
  EXPECT_NEAR(p.tracker.wall_lattice.gate_rad, 3.0 * M_PI / 180.0, 1e-12);
  EXPECT_EQ(p.tracker.wall_lattice.min_points, 20);
  XmlRpc::XmlRpcValue bad;
  bad["wall_lattice"]["gate_deg"] = 45.0;  // every line would be a wall of the lattice
  bad["wall_lattice"]["gate_m"] = 0.1;     // not a key of the lattice
  bad["profile_min_height_m"] = 3.0;       // above profile_max_height_m
  const auto errors = ReadSensed(bad, &p);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_TRUE(Names(errors, "~wall_lattice/gate_deg must be > 0 and below 45 degrees"));
  EXPECT_TRUE(Names(errors, "wall_lattice/gate_m"));
  EXPECT_TRUE(Names(errors, "profile_max_height_m"));
}

}  // namespace
}  // namespace markov_localization
