#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "robot_sim/robot_spec.h"
#include "test_world.h"

namespace robot_sim {
namespace {

using testing::PackageFile;

RobotSpec Load(const std::string& name) {
  auto r = LoadRobotSpec(PackageFile("config/robots/" + name + ".yaml"),
                         PackageFile("urdf/" + name + ".urdf"));
  if (!r.ok()) throw std::runtime_error(spott_map::FormatErrors(r.errors));
  return *r.spec;
}

std::string ReadFile(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(RobotSpecTest, Nomad200RingsComeFromTheUrdf) {
  const RobotSpec nomad = Load("nomad200");
  EXPECT_NEAR(nomad.radius_m, 0.2285, 1e-9);
  EXPECT_EQ(nomad.drive.kind, DriveKind::kSynchro);
  const RangeRingSpec* sonar = nomad.FindRing("sonar");
  ASSERT_NE(sonar, nullptr);
  ASSERT_EQ(sonar->mounts.size(), 16u);
  // sonar_5 is the fifth of 16 every 22.5 degrees: 90 degrees, on the rim, 0.65 m up.
  EXPECT_EQ(sonar->mounts[4].frame_id, "sonar_5");
  EXPECT_NEAR(sonar->mounts[4].yaw, M_PI / 2, 1e-6);
  EXPECT_NEAR(sonar->mounts[4].x, 0.0, 1e-4);
  EXPECT_NEAR(sonar->mounts[4].y, 0.2285, 1e-4);
  EXPECT_NEAR(sonar->mounts[4].z, 0.65, 1e-4);
  EXPECT_EQ(sonar->vertical_rays, 3);  // a cone: it hears what is lower than the ring
  ASSERT_NE(nomad.FindRing("infrared"), nullptr);
  EXPECT_EQ(nomad.FindRing("infrared")->vertical_rays, 1);
  EXPECT_EQ(nomad.FindRing("infrared")->mounts.size(), 16u);
  ASSERT_TRUE(nomad.bumper);
  EXPECT_EQ(nomad.bumper->segments, 20);
  EXPECT_FALSE(nomad.laser);
}

TEST(RobotSpecTest, B21HasTwentyFourSonarsAndAFrontLaser) {
  const RobotSpec b21 = Load("b21");
  EXPECT_EQ(b21.FindRing("sonar")->mounts.size(), 24u);
  EXPECT_NEAR(b21.FindRing("sonar")->mounts[1].yaw, 15 * M_PI / 180, 1e-6);
  ASSERT_TRUE(b21.laser);
  EXPECT_NEAR(b21.laser->mount.x, 0.15, 1e-9);
  EXPECT_NEAR(b21.laser->mount.z, 0.40, 1e-9);
  EXPECT_EQ(b21.laser->beams, 181);
}

TEST(RobotSpecTest, B12AndHilare) {
  const RobotSpec b12 = Load("b12");
  EXPECT_EQ(b12.FindRing("sonar")->mounts.size(), 12u);
  EXPECT_NEAR(b12.radius_m, 0.1525, 1e-9);
  const RobotSpec hilare = Load("hilare");
  EXPECT_EQ(hilare.drive.kind, DriveKind::kDifferential);
  EXPECT_EQ(hilare.FindRing("sonar")->mounts.size(), 16u);
  EXPECT_EQ(hilare.FindRing("sonar")->mounts[0].frame_id, "sonar_1");
  ASSERT_TRUE(hilare.laser);
  EXPECT_NEAR(hilare.laser->mount.x, 0.2, 1e-9);  // through the pan joint
  EXPECT_NEAR(hilare.laser->mount.z, 0.95, 1e-9);
}

TEST(RobotSpecTest, YamlErrorsNameFileLineAndColumn) {
  const std::string urdf = ReadFile(PackageFile("urdf/b12.urdf"));
  const std::string yaml =
      "name: b12\n"
      "drive: {kind: synchro, max_linear_mps: 0.5, max_angular_rps: 1,\n"
      "        max_linear_accel: 1, max_angular_accel: 1, wheelbase: 2}\n";
  const auto r = LoadRobotSpecFromStrings(yaml, "bad.yaml", urdf, "b12.urdf");
  ASSERT_FALSE(r.ok());
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].where.file, "bad.yaml");
  EXPECT_EQ(r.errors[0].where.line, 3);
  EXPECT_NE(r.errors[0].message.find("wheelbase"), std::string::npos);
}

// robot_file_fuzz: `rays: 8.9e61` overflowed the int it was cast to. Every count is a whole
// number in its range, refused by name and line otherwise.
TEST(RobotSpecTest, CountsOutOfRangeOrFractionalAreRefusedByName) {
  const std::string urdf = ReadFile(PackageFile("urdf/b12.urdf"));
  const std::string head =
      "name: b12\n"
      "drive: {kind: synchro, max_linear_mps: 0.5, max_angular_rps: 1,\n"
      "        max_linear_accel: 1, max_angular_accel: 1}\n";
  const auto ring = [](const std::string& rays, const std::string& groups) {
    return "rings:\n  - {name: sonar, kind: ultrasound, link_prefix: sonar_, field_of_view: 0.4,\n"
           "     min_range: 0.15, max_range: 6, rays: " +
           rays + ", critical_angle: 0.35, noise_stddev: 0, fire_groups: " + groups + "}\n";
  };
  for (const auto& [rays, groups, key] :
       {std::tuple{"88888888888888888888888888888888888888888888888888888888888887", "1", "rays"},
        std::tuple{"7.5", "1", "rays"}, std::tuple{"7", "1e300", "fire_groups"},
        std::tuple{"0", "1", "rays"}}) {
    const auto r =
        LoadRobotSpecFromStrings(head + ring(rays, groups), "bad.yaml", urdf, "b12.urdf");
    ASSERT_FALSE(r.ok()) << rays << " " << groups;
    const std::string errors = spott_map::FormatErrors(r.errors);
    EXPECT_NE(errors.find(std::string("bad.yaml:6:")), std::string::npos) << errors;
    EXPECT_NE(errors.find(std::string(key) + " must be a whole number in [1, 1000]"),
              std::string::npos)
        << errors;
  }
  const auto rows = LoadRobotSpecFromStrings(
      head +
          "rings:\n  - {name: sonar, kind: ultrasound, link_prefix: sonar_, field_of_view: "
          "0.4,\n     max_range: 6, rays: 7, vertical_rays: 0, critical_angle: 0.35}\n",
      "bad.yaml", urdf, "b12.urdf");
  ASSERT_FALSE(rows.ok());
  const std::string rows_errors = spott_map::FormatErrors(rows.errors);
  EXPECT_NE(rows_errors.find("bad.yaml:6:"), std::string::npos) << rows_errors;
  EXPECT_NE(rows_errors.find("vertical_rays must be a whole number in [1, 100]"), std::string::npos)
      << rows_errors;
  const auto bumper = LoadRobotSpecFromStrings(head + "bumper: {segments: 1e20, travel_m: 0.01}\n",
                                               "bad.yaml", urdf, "b12.urdf");
  ASSERT_FALSE(bumper.ok());
  EXPECT_NE(
      spott_map::FormatErrors(bumper.errors).find("segments must be a whole number in [1, 360]"),
      std::string::npos)
      << spott_map::FormatErrors(bumper.errors);
}

TEST(RobotSpecTest, RingWithoutUrdfLinksIsAnError) {
  const std::string urdf = ReadFile(PackageFile("urdf/b12.urdf"));
  const std::string yaml =
      "name: b12\n"
      "drive: {kind: synchro, max_linear_mps: 0.5, max_angular_rps: 1,\n"
      "        max_linear_accel: 1, max_angular_accel: 1}\n"
      "rings:\n"
      "  - {name: infrared, kind: infrared, link_prefix: ir_, field_of_view: 0.1, min_range: 0,\n"
      "     max_range: 0.6, rays: 1, critical_angle: 1.5, noise_stddev: 0}\n";
  const auto r = LoadRobotSpecFromStrings(yaml, "b12.yaml", urdf, "b12.urdf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("ir_1"), std::string::npos);
  EXPECT_EQ(r.errors[0].where.file, "b12.urdf");
}

TEST(RobotSpecTest, UnreadableUrdfAndMissingFilesAreErrors) {
  const std::string yaml = ReadFile(PackageFile("config/robots/b12.yaml"));
  EXPECT_FALSE(LoadRobotSpecFromStrings(yaml, "b12.yaml", "<robot", "x.urdf").ok());
  EXPECT_FALSE(LoadRobotSpecFromStrings(yaml, "b12.yaml", "", "x.urdf").ok());
  const auto r = LoadRobotSpec("/nonexistent/robot.yaml", PackageFile("urdf/b12.urdf"));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].ToString().find("/nonexistent/robot.yaml"), std::string::npos);
}

}  // namespace
}  // namespace robot_sim
