#include "spott_map/geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace spott_map {
namespace {

TEST(Geometry, DistancePointSegmentUsesTheNearestEndOrTheFoot) {
  const Segment s{Vec2(0, 0), Vec2(4, 0)};
  EXPECT_DOUBLE_EQ(DistancePointSegment(Vec2(2, 3), s), 3.0);    // foot inside
  EXPECT_DOUBLE_EQ(DistancePointSegment(Vec2(7, 4), s), 5.0);    // beyond b: 3-4-5
  EXPECT_DOUBLE_EQ(DistancePointSegment(Vec2(-3, -4), s), 5.0);  // before a
}

TEST(Geometry, ProperCrossingExcludesTouchingAndCollinearOverlap) {
  const Segment s{Vec2(0, 0), Vec2(2, 2)};
  EXPECT_TRUE(SegmentsCrossProperly(s, Segment{Vec2(0, 2), Vec2(2, 0)}));
  EXPECT_FALSE(SegmentsCrossProperly(s, Segment{Vec2(2, 2), Vec2(3, 0)}));  // shares an end
  EXPECT_FALSE(SegmentsCrossProperly(s, Segment{Vec2(1, 1), Vec2(3, 3)}));  // collinear
  EXPECT_FALSE(SegmentsCrossProperly(s, Segment{Vec2(3, 0), Vec2(4, 1)}));
}

TEST(Geometry, LatticeWindowPutsItsCornerOnTheCellLattice) {
  // 20 cells of 0.2 m centred on (3.05, 5.13): the corner (1.05, 3.13) snaps to (1.0, 3.2).
  const Box w = LatticeWindow(Vec2(3.05, 5.13), 20, 0.2);
  EXPECT_NEAR(w.min.x(), 1.0, 1e-12);
  EXPECT_NEAR(w.min.y(), 3.2, 1e-12);
  EXPECT_NEAR(w.max.x(), 5.0, 1e-12);
  EXPECT_NEAR(w.max.y(), 7.2, 1e-12);
  // A move smaller than half a cell keeps the same window: successive windows share cells.
  const Box v = LatticeWindow(Vec2(3.08, 5.15), 20, 0.2);
  EXPECT_TRUE(v.min.isApprox(w.min) && v.max.isApprox(w.max));
}

TEST(Geometry, SegmentIntersectionPoint) {
  auto p = SegmentIntersection(Segment{Vec2(0, 0), Vec2(4, 4)}, Segment{Vec2(0, 4), Vec2(4, 0)});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x(), 2.0, 1e-12);
  EXPECT_NEAR(p->y(), 2.0, 1e-12);
  EXPECT_FALSE(
      SegmentIntersection(Segment{Vec2(0, 0), Vec2(1, 0)}, Segment{Vec2(0, 1), Vec2(1, 1)}));
  // Collinear and overlapping: not a single point.
  EXPECT_FALSE(
      SegmentIntersection(Segment{Vec2(0, 0), Vec2(2, 0)}, Segment{Vec2(1, 0), Vec2(3, 0)}));
  // Collinear, end to end: the shared end.
  auto q = SegmentIntersection(Segment{Vec2(0, 0), Vec2(1, 0)}, Segment{Vec2(1, 0), Vec2(3, 0)});
  ASSERT_TRUE(q);
  EXPECT_NEAR(q->x(), 1.0, 1e-12);
}

TEST(Geometry, AreaAndCentroidOfAnLShape) {
  // 2x2 square with the top-right 1x1 square removed: area 3, centroid (5/6, 5/6).
  const Polygon l{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
  EXPECT_DOUBLE_EQ(SignedArea(l), 3.0);
  Polygon reversed(l.rbegin(), l.rend());
  EXPECT_DOUBLE_EQ(SignedArea(reversed), -3.0);
  const Vec2 c = Centroid(l);
  EXPECT_NEAR(c.x(), 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(c.y(), 5.0 / 6.0, 1e-12);
}

TEST(Geometry, SelfIntersectionOfABowTieIsFound) {
  const Polygon bow_tie{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)};
  auto crossing = FindSelfIntersection(bow_tie);
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->first, 0u);
  EXPECT_EQ(crossing->second, 2u);
  const Polygon square{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  EXPECT_FALSE(FindSelfIntersection(square));
  // An edge that folds back on the previous one.
  const Polygon spike{Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)};
  EXPECT_TRUE(FindSelfIntersection(spike));
}

TEST(Geometry, PointInPolygonCountsTheBoundaryAsInside) {
  const Polygon square{Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
  EXPECT_TRUE(PointInPolygon(Vec2(1, 1), square));
  EXPECT_TRUE(PointInPolygon(Vec2(2, 1), square));
  EXPECT_TRUE(PointInPolygon(Vec2(0, 0), square));
  EXPECT_FALSE(PointInPolygon(Vec2(2.01, 1), square));
  EXPECT_FALSE(PointInPolygon(Vec2(-1, -1), square));
}

TEST(Geometry, PolygonsSharingAnEdgeDoNotOverlap) {
  const Polygon a{Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
  const Polygon b{Vec2(2, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 2)};
  const Polygon c{Vec2(1, 1), Vec2(3, 1), Vec2(3, 3), Vec2(1, 3)};
  EXPECT_FALSE(PolygonsOverlap(a, b, 0.01));
  EXPECT_TRUE(PolygonsOverlap(a, c, 0.01));
  EXPECT_TRUE(PolygonsOverlap(a, a, 0.01));  // the same room twice
  const Polygon inner{Vec2(0.5, 0.5), Vec2(1.5, 0.5), Vec2(1.5, 1.5), Vec2(0.5, 1.5)};
  EXPECT_TRUE(PolygonsOverlap(a, inner, 0.01));
}

TEST(Geometry, NormalizeAngleWrapsIntoHalfOpenInterval) {
  EXPECT_NEAR(NormalizeAngle(3 * M_PI), M_PI, 1e-12);
  EXPECT_NEAR(NormalizeAngle(-M_PI), M_PI, 1e-12);
  EXPECT_NEAR(NormalizeAngle(0.5 - 4 * M_PI), 0.5, 1e-12);
}

}  // namespace
}  // namespace spott_map

namespace spott_map {
namespace {

TEST(Geometry, OverlapThroughVerticesIsFound) {
  // b's corners lie on a's top and bottom edges and a's corners on b's: no edge crosses another
  // properly and no vertex is strictly inside, yet the interiors share a 1 x 4 m strip.
  const Polygon a{Vec2(0, 0), Vec2(4, 0), Vec2(4, 4), Vec2(0, 4)};
  const Polygon b{Vec2(3, 0), Vec2(8, 0), Vec2(8, 4), Vec2(3, 4)};
  EXPECT_TRUE(PolygonsOverlap(a, b, 0.02));
  // An L-shaped room and a room filling its notch share two edges and do not overlap.
  const Polygon l{Vec2(0, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 2), Vec2(2, 4), Vec2(0, 4)};
  const Polygon notch{Vec2(2, 2), Vec2(4, 2), Vec2(4, 4), Vec2(2, 4)};
  EXPECT_FALSE(PolygonsOverlap(l, notch, 0.02));
  EXPECT_FALSE(PolygonsOverlap(notch, l, 0.02));
}

}  // namespace
}  // namespace spott_map
