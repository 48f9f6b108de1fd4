// The published estimate among twin modes (StickyEstimate) and the shift of a* out of the
// planner's padding (NavigableTarget).
#include <gtest/gtest.h>

#include <cmath>

#include "markov_localization/navigable_target.h"
#include "markov_localization/sticky_estimate.h"

namespace markov_localization {
namespace {

Mode At(double x, double y, double yaw, double mass) {
  Mode m;
  m.mean = Pose2{x, y, yaw};
  m.mass = mass;
  return m;
}

TEST(StickyEstimate, MapToOdomAndComposeAreInverse) {
  const Pose2 e{5.0, -2.0, 2.5}, o{1.0, 3.0, -0.7};
  const Pose2 back = Compose(MapToOdom(e, o), o);
  EXPECT_NEAR(back.x, e.x, 1e-12);
  EXPECT_NEAR(back.y, e.y, 1e-12);
  EXPECT_NEAR(back.yaw, e.yaw, 1e-12);
}

TEST(StickyEstimate, StaysWithTheFollowedTwinUntilTheOtherIsTwiceAsHeavy) {
  StickyEstimate sticky;  // switch_ratio 2
  const Pose2 odom0{0, 0, 0};
  // First scan: the twin at (5, 10) is the heaviest and holds the maximum.
  const Mode a = At(5.0, 10.0, 0.0, 0.50), b = At(22.0, 10.0, M_PI, 0.49);
  Pose2 e = sticky.Select({a, b}, Pose2{5.05, 10.0, 0.0}, odom0);
  EXPECT_NEAR(e.x, 5.05, 1e-12);  // the refined pose of the maximum
  // The robot drives 1 m ahead (odometry); the twins move along, and now b is slightly heavier
  // and holds the maximum: the estimate stays with a (its mean).
  const Pose2 odom1{1.0, 0, 0};
  const Mode a1 = At(6.0, 10.0, 0.0, 0.49), b1 = At(21.0, 10.0, M_PI, 0.50);
  bool switched = true;
  e = sticky.Select({b1, a1}, Pose2{21.0, 10.0, M_PI}, odom1, &switched);
  EXPECT_FALSE(switched);
  EXPECT_NEAR(e.x, 6.0, 1e-12);
  EXPECT_NEAR(e.yaw, 0.0, 1e-12);
  // b grows to 2.5 times a's mass: the estimate moves to it.
  const Mode a2 = At(6.0, 10.0, 0.0, 0.2), b2 = At(21.0, 10.0, M_PI, 0.5);
  e = sticky.Select({b2, a2}, Pose2{21.02, 10.0, M_PI}, odom1, &switched);
  EXPECT_TRUE(switched);
  EXPECT_NEAR(e.x, 21.02, 1e-12);
  // After a reset nothing is followed: the maximum.
  sticky.Reset();
  e = sticky.Select({a1, b1}, Pose2{21.0, 10.0, M_PI}, odom1, &switched);
  EXPECT_FALSE(switched);
  EXPECT_NEAR(e.x, 21.0, 1e-12);
}

TEST(StickyEstimate, TheHeaviestFollowedModeGetsItsMeanWhenTheMaximumIsInTheTwin) {
  StickyEstimate sticky;
  const Pose2 odom{0, 0, 0};
  sticky.Select({At(5, 10, 0, 0.6), At(22, 10, M_PI, 0.4)}, Pose2{5, 10, 0}, odom);
  // Still the heaviest, but a peakier twin holds the global maximum.
  const Pose2 e =
      sticky.Select({At(5.1, 10, 0, 0.6), At(22, 10, M_PI, 0.4)}, Pose2{22, 10, M_PI}, odom);
  EXPECT_NEAR(e.x, 5.1, 1e-12);
}

// A 0.9 m doorway in a 0.2 m wall between two free rooms, 5 cm cells.
MapModel Doorway() {
  const double res = 0.05;
  const int w = 80, h = 80;  // 4 x 4 m
  std::vector<std::int8_t> data(static_cast<std::size_t>(w) * h, 0);
  for (int iy = 0; iy < h; ++iy)
    for (int ix = 0; ix < w; ++ix) {
      const double x = (ix + 0.5) * res, y = (iy + 0.5) * res;
      if (y > 1.9 && y < 2.1 && !(x > 1.55 && x < 2.45)) data[iy * w + ix] = 100;
    }
  return MapModel::FromOccupancy(Vec2(0, 0), w, h, res, data, 50, 0.1);
}

TEST(NavigableTarget, ClearanceIsTheDistanceToTheNearestObstacle) {
  const MapModel map = Doorway();
  EXPECT_NEAR(Clearance(map, Vec2(1.0, 1.0), 2.0), 0.9, 0.06);  // wall above
  // Below the doorway: the nearest obstacle is the jamb corner (1.55, 1.9), 1.0 m away.
  EXPECT_NEAR(Clearance(map, Vec2(2.0, 1.0), 2.0), std::hypot(0.45, 0.9), 0.08);
  EXPECT_NEAR(Clearance(map, Vec2(2.0, 2.0), 2.0), 0.45, 0.06);  // jambs at 1.55 and 2.45
  EXPECT_NEAR(Clearance(map, Vec2(3.9, 0.5), 0.3), 0.3, 1e-9);   // capped (grid edge is free)
}

TEST(NavigableTarget, ATargetBesideTheDoorwayMovesToItsMiddle) {
  const MapModel map = Doorway();
  // a* 0.25 m off the doorway's centre line: 0.2 m from the jamb, inside a 0.33 m padding.
  const auto t = NavigableTarget(map, Vec2(2.25, 2.0), 0.33, 0.75);
  ASSERT_TRUE(t);
  EXPECT_GE(Clearance(map, *t, 1.0), 0.33);
  EXPECT_NEAR(t->y(), 2.0, 0.11);  // still in the doorway
  EXPECT_LT((*t - Vec2(2.25, 2.0)).norm(), 0.2);
  // A target with room to spare stays where it is.
  const auto free = NavigableTarget(map, Vec2(1.0, 1.0), 0.33, 0.75);
  ASSERT_TRUE(free);
  EXPECT_NEAR((*free - Vec2(1.0, 1.0)).norm(), 0.0, 1e-9);
  // Nothing with 0.6 m clearance near the doorway.
  EXPECT_FALSE(NavigableTarget(map, Vec2(2.0, 2.0), 0.6, 0.3));
}

}  // namespace
}  // namespace markov_localization
