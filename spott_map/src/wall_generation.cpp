#include "spott_map/wall_generation.h"

#include <algorithm>
#include <cmath>

namespace spott_map {

namespace {

// A line in the plane: unit direction (canonical sign) and signed offset from the origin.
struct Line {
  Vec2 direction;
  double offset = 0.0;
};

Line LineThrough(const Segment& s) {
  Vec2 d = s.Direction();
  if (d.x() < -1e-12 || (std::abs(d.x()) <= 1e-12 && d.y() < 0.0)) d = -d;
  return Line{d, Cross(d, s.a)};
}

bool SameLine(const Line& a, const Line& b, double tolerance) {
  return std::abs(Cross(a.direction, b.direction)) < 1e-6 &&
         std::abs(a.offset - b.offset) < tolerance;
}

using Interval = std::pair<double, double>;

std::vector<Interval> Union(std::vector<Interval> intervals, double tolerance) {
  std::sort(intervals.begin(), intervals.end());
  std::vector<Interval> merged;
  for (const Interval& i : intervals) {
    if (!merged.empty() && i.first <= merged.back().second + tolerance) {
      merged.back().second = std::max(merged.back().second, i.second);
    } else {
      merged.push_back(i);
    }
  }
  return merged;
}

std::vector<Interval> Subtract(const std::vector<Interval>& from, const Interval& cut) {
  std::vector<Interval> out;
  for (const Interval& i : from) {
    if (cut.second <= i.first || cut.first >= i.second) {
      out.push_back(i);
      continue;
    }
    if (cut.first > i.first) out.emplace_back(i.first, cut.first);
    if (cut.second < i.second) out.emplace_back(cut.second, i.second);
  }
  return out;
}

}  // namespace

std::vector<Wall> GenerateWallsFromRooms(const std::vector<Room>& rooms,
                                         const std::vector<Door>& doors, double thickness,
                                         double tolerance) {
  struct Run {
    Line line;
    std::vector<Interval> intervals;
  };
  std::vector<Run> runs;
  for (const Room& room : rooms) {
    for (std::size_t i = 0; i < room.polygon.size(); ++i) {
      const Segment edge = PolygonEdge(room.polygon, i);
      if (edge.Length() <= tolerance) continue;
      const Line line = LineThrough(edge);
      const double t0 = line.direction.dot(edge.a);
      const double t1 = line.direction.dot(edge.b);
      const Interval interval(std::min(t0, t1), std::max(t0, t1));
      auto run = std::find_if(runs.begin(), runs.end(),
                              [&](const Run& r) { return SameLine(r.line, line, tolerance); });
      if (run == runs.end()) {
        runs.push_back(Run{line, {interval}});
      } else {
        run->intervals.push_back(interval);
      }
    }
  }
  std::vector<Wall> walls;
  for (Run& run : runs) {
    std::vector<Interval> pieces = Union(run.intervals, tolerance);
    for (const Door& door : doors) {
      if (door.opening.Length() <= 0.0) continue;
      if (!SameLine(run.line, LineThrough(door.opening), tolerance)) continue;
      const double t0 = run.line.direction.dot(door.opening.a);
      const double t1 = run.line.direction.dot(door.opening.b);
      pieces = Subtract(pieces, Interval(std::min(t0, t1), std::max(t0, t1)));
    }
    const Vec2 normal(-run.line.direction.y(), run.line.direction.x());
    for (const Interval& piece : pieces) {
      if (piece.second - piece.first <= tolerance) continue;
      Wall wall;
      wall.id = "wall_" + std::to_string(walls.size());
      wall.segment = Segment{normal * run.line.offset + run.line.direction * piece.first,
                             normal * run.line.offset + run.line.direction * piece.second};
      wall.thickness = thickness;
      wall.generated = true;
      walls.push_back(wall);
    }
  }
  return walls;
}

}  // namespace spott_map
