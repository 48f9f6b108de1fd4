#include "spott_tr_plus/controller/sensor_mapper.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>
#include <unordered_set>

#include <Eigen/Eigenvalues>

#include "spott_map/local_map.h"
#include "violation.h"

namespace spott_tr_plus::controller {

namespace {

enum Flag : std::uint8_t {
  kKnown = 1,       // within known_tolerance_m of a map feature or a closed door
  kBlocked = 2,     // a map obstacle meets the cell
  kDoor = 4,        // in a door opening's zone
  kOutside = 8,     // outside every room
  kConfirmed = 16,  // confirmed (sent to Take once)
  kNear = 32,       // within near_miss_m of a map feature (kKnown's band and beyond it)
  kOwn = 64         // within known_tolerance_m of a feature this mapper made
};

}  // namespace

std::vector<std::string> ValidateParameters(const MappingParameters& p) {
  std::vector<std::string> v;
  const auto positive = [&](const char* n, double x) {
    if (!(std::isfinite(x) && x > 0)) v.push_back(Violation(n, "> 0", x));
  };
  const auto non_negative = [&](const char* n, double x) {
    if (!(std::isfinite(x) && x >= 0)) v.push_back(Violation(n, ">= 0", x));
  };
  if (!(p.cell_m >= 0.02 && p.cell_m <= 0.5))
    v.push_back(Violation("cell_m", "in [0.02, 0.5]", p.cell_m));
  positive("sonar_max_range_m", p.sonar_max_range_m);
  non_negative("sonar_min_margin_m", p.sonar_min_margin_m);
  positive("range_finder_max_range_m", p.range_finder_max_range_m);
  if (p.sonar_hit_score < 1) v.push_back(Violation("sonar_hit_score", ">= 1", p.sonar_hit_score));
  if (p.range_finder_hit_score < 1)
    v.push_back(Violation("range_finder_hit_score", ">= 1", p.range_finder_hit_score));
  if (p.miss_score < 0) v.push_back(Violation("miss_score", ">= 0", p.miss_score));
  if (p.confirm_score < 1) v.push_back(Violation("confirm_score", ">= 1", p.confirm_score));
  if (p.max_score < p.confirm_score || p.max_score > 127)
    v.push_back(Violation("max_score", "in [confirm_score, 127]", p.max_score));
  non_negative("known_tolerance_m", p.known_tolerance_m);
  if (!(std::isfinite(p.near_miss_m) && p.near_miss_m >= 0 && p.near_miss_m <= 5))
    v.push_back(Violation("near_miss_m", "in [0, 5]", p.near_miss_m));
  if (p.near_miss_points < 1)
    v.push_back(Violation("near_miss_points", ">= 1", p.near_miss_points));
  positive("door_zone_m", p.door_zone_m);
  positive("segment_residual_m", p.segment_residual_m);
  positive("cluster_gap_m", p.cluster_gap_m);
  positive("echo_cluster_gap_m", p.echo_cluster_gap_m);
  if (!(p.mapless_extent_m >= 5 && p.mapless_extent_m <= 200))
    v.push_back(Violation("mapless_extent_m", "in [5, 200]", p.mapless_extent_m));
  positive("echo_tolerance_m", p.echo_fit.tolerance_base_m);
  non_negative("echo_tolerance_per_m", p.echo_fit.tolerance_per_m);
  if (!(p.echo_fit.max_incidence_rad >= 0 && p.echo_fit.max_incidence_rad < M_PI / 2))
    v.push_back(Violation("sonar_max_incidence_rad", "in [0, pi/2)", p.echo_fit.max_incidence_rad));
  if (!(p.echo_fit.max_direction_error_rad > 0 && p.echo_fit.max_direction_error_rad < 1))
    v.push_back(
        Violation("echo_max_direction_error_rad", "in (0, 1)", p.echo_fit.max_direction_error_rad));
  if (p.echoes_per_cell < 1 || p.echoes_per_cell > 64)
    v.push_back(Violation("echoes_per_cell", "in [1, 64]", p.echoes_per_cell));
  return v;
}

std::vector<std::string> ValidateParameters(const DoorSensingParameters& p) {
  std::vector<std::string> v;
  if (!(std::isfinite(p.range_m) && p.range_m > 0))
    v.push_back(Violation("range_m", "> 0", p.range_m));
  if (!(std::isfinite(p.end_margin_m) && p.end_margin_m >= 0))
    v.push_back(Violation("end_margin_m", ">= 0", p.end_margin_m));
  if (!(std::isfinite(p.pose_error_m) && p.pose_error_m >= 0))
    v.push_back(Violation("pose_error_m", ">= 0", p.pose_error_m));
  if (!(std::isfinite(p.match_m) && p.match_m > 0))
    v.push_back(Violation("match_m", "> 0", p.match_m));
  if (!(std::isfinite(p.beyond_m) && p.beyond_m > 0))
    v.push_back(Violation("beyond_m", "> 0", p.beyond_m));
  if (!(p.normal_angle_rad >= 0 && p.normal_angle_rad < M_PI / 2))
    v.push_back(Violation("normal_angle_rad", "in [0, pi/2)", p.normal_angle_rad));
  if (!(p.profile_normal_angle_rad >= 0 && p.profile_normal_angle_rad < M_PI / 2))
    v.push_back(Violation("profile_normal_angle_rad", "in [0, pi/2)", p.profile_normal_angle_rad));
  if (p.votes < 1) v.push_back(Violation("votes", ">= 1", p.votes));
  if (p.max_votes < p.votes) v.push_back(Violation("max_votes", ">= votes", p.max_votes));
  return v;
}

SensorMapper::SensorMapper(std::string sensor, MappingParameters mapping,
                           DoorSensingParameters doors, bool sense_doors)
    : sensor_(std::move(sensor)), p_(mapping), d_(doors), sense_doors_(sense_doors) {}

void SensorMapper::SetMap(const spott_map::MapDatabase& db, const std::optional<Vec2>& robot) {
  // The grid covers every room (with a margin); it is laid out once, at the first map.
  const bool rooms = !db.graph().rooms().empty();
  if (!rooms && !robot && !have_map_) return;
  if (!have_map_) {
    spott_map::Box box;
    bool any = false;
    const auto include = [&](const spott_map::Box& b) {
      if (!any) box = b;
      box.min = box.min.cwiseMin(b.min);
      box.max = box.max.cwiseMax(b.max);
      any = true;
    };
    if (rooms) {
      for (const spott_map::Room& r : db.graph().rooms())
        include(spott_map::BoundingBox(r.polygon));
      for (const spott_map::MapFeature& f : db.features()) include(f.Bounds());
    } else {
      const Vec2 half = Vec2::Constant(p_.mapless_extent_m / 2);
      include(spott_map::Box{*robot - half, *robot + half});
    }
    if (!any) return;
    box = box.Inflated(1.0);
    origin_ = box.min;
    width_ = std::max(1, static_cast<int>(std::ceil((box.max.x() - box.min.x()) / p_.cell_m)));
    height_ = std::max(1, static_cast<int>(std::ceil((box.max.y() - box.min.y()) / p_.cell_m)));
    score_.assign(static_cast<std::size_t>(width_) * height_, 0);
    echoes_.assign(score_.size(), EchoMean{});
    flags_.assign(score_.size(), 0);
    have_map_ = true;
  }
  // What does not change while the robot runs (the rooms, the doors' openings): once.
  if (doors_.empty() && !static_drawn_) {
    for (const spott_map::Door& door : db.graph().doors()) {
      if (door.kind != spott_map::DoorKind::kDoor) continue;
      doors_.push_back({door.id, door.opening});
      door_votes_[door.id] = 0;
    }
    for (int iy = 0; iy < height_; ++iy) {
      for (int ix = 0; ix < width_; ++ix) {
        const Vec2 c = origin_ + p_.cell_m * Vec2(ix + 0.5, iy + 0.5);
        std::uint8_t& f = flags_[Index(ix, iy)];
        if (rooms && !db.graph().RoomContaining(c)) f |= kOutside;
        for (const DoorZone& z : doors_) {
          const Vec2 dir = z.opening.Direction();
          const spott_map::Segment longer{z.opening.a - 0.1 * dir, z.opening.b + 0.1 * dir};
          if (spott_map::DistancePointSegment(c, longer) <= p_.door_zone_m) {
            f |= kDoor;
            break;
          }
        }
      }
    }
    static_drawn_ = true;
  }
  // What the map holds now: known (within the tolerance of a feature or a closed door) and
  // blocked (an obstacle meets the cell). The mapper's own features are neither: its echoes
  // keep voting there, so that a wall seen bit by bit grows into one segment (Take re-fuses
  // the whole cluster) instead of a row of points each hiding the next echoes.
  spott_map::OccupancyRaster known(origin_, width_, height_, p_.cell_m);
  spott_map::OccupancyRaster blocked(origin_, width_, height_, p_.cell_m);
  spott_map::OccupancyRaster near(origin_, width_, height_, p_.cell_m);
  spott_map::OccupancyRaster own(origin_, width_, height_, p_.cell_m);
  const bool near_check = p_.near_miss_m > p_.known_tolerance_m;
  const auto draw = [&](const spott_map::MapFeature& f) {
    if (IsOwn(f)) {
      spott_map::RasterizeFeature(f, p_.known_tolerance_m, own);
    } else {
      spott_map::RasterizeFeature(f, p_.known_tolerance_m, known);
      spott_map::RasterizeFeature(f, 0.0, blocked);
    }
    if (near_check) spott_map::RasterizeFeature(f, p_.near_miss_m, near);
  };
  const spott_map::Box area = known.Bounds().Inflated(p_.near_miss_m + p_.cell_m);
  for (const spott_map::MapFeature* f : db.FeaturesIn(area)) draw(*f);
  for (const spott_map::Door& door : db.graph().doors()) {
    if (door.state != spott_map::DoorState::kClosed) continue;
    draw(spott_map::MakeSegment(door.id, door.opening, "door", 0.05));
  }
  for (int iy = 0; iy < height_; ++iy) {
    for (int ix = 0; ix < width_; ++ix) {
      std::uint8_t& f = flags_[Index(ix, iy)];
      f &= static_cast<std::uint8_t>(kConfirmed | kDoor | kOutside);
      if (known.at(ix, iy) != spott_map::Cell::kFree) f |= kKnown;
      if (own.at(ix, iy) != spott_map::Cell::kFree) f |= kOwn;
      if (near.at(ix, iy) != spott_map::Cell::kFree) f |= kNear;
      if (blocked.at(ix, iy) == spott_map::Cell::kObstacle) f |= kBlocked;
    }
  }
  if (reseed_) Reseed(db);
  revision_ = db.revision();
}

bool SensorMapper::CellOf(const Vec2& p, int* ix, int* iy) const {
  // Compared before the cast: a point 1e39 m away (a profile's finite but absurd sample) would
  // overflow an int (found by controller_messages_fuzz).
  const double fx = std::floor((p.x() - origin_.x()) / p_.cell_m);
  const double fy = std::floor((p.y() - origin_.y()) / p_.cell_m);
  if (!(fx >= 0 && fy >= 0 && fx < width_ && fy < height_)) return false;
  *ix = static_cast<int>(fx);
  *iy = static_cast<int>(fy);
  return true;
}

int SensorMapper::Score(const Vec2& p) const {
  if (!have_map_) return 0;
  int ix, iy;
  if (!CellOf(p, &ix, &iy)) return 0;
  return score_[Index(ix, iy)];
}

bool SensorMapper::ArcMeetsKnown(const Vec2& from, double angle, double range,
                                 double half_cone) const {
  if (half_cone <= 0.0) return false;
  // Sampled at half a cell along the arc, on three radii half a cell apart.
  const int n =
      std::max(1, static_cast<int>(std::ceil(2.0 * half_cone * range / (0.5 * p_.cell_m))));
  for (const double r : {range - 0.5 * p_.cell_m, range, range + 0.5 * p_.cell_m}) {
    for (int k = 0; k <= n; ++k) {
      const double a = angle - half_cone + 2.0 * half_cone * k / n;
      const Vec2 q = from + r * Vec2(std::cos(a), std::sin(a));
      int ix, iy;
      if (!CellOf(q, &ix, &iy)) continue;
      if (flags_[Index(ix, iy)] & kBlocked) return true;
    }
  }
  return false;
}

void SensorMapper::Beam(const Vec2& from, double angle, double range, bool echo, double max_range,
                        int hit, double half_cone) {
  if (!echo || !have_map_) return;
  const Vec2 dir(std::cos(angle), std::sin(angle));
  const double free_to = std::min(range, max_range) - p_.cell_m;
  const double step = 0.5 * p_.cell_m;
  bool crossed = false;
  int last = -1;
  for (double s = 0.0; s < free_to; s += step) {
    const Vec2 q = from + s * dir;
    int ix, iy;
    if (!CellOf(q, &ix, &iy)) return;
    const int index = static_cast<int>(Index(ix, iy));
    if (index == last) continue;
    last = index;
    // A known obstacle crossed well before the echo: what echoed lies beyond it (a reflection).
    if ((flags_[index] & kBlocked) && s > 0.05 && s < range - p_.known_tolerance_m) crossed = true;
    if (!(flags_[index] & kConfirmed)) {
      score_[index] =
          static_cast<std::int8_t>(std::max(-p_.max_score, score_[index] - p_.miss_score));
    }
  }
  if (crossed || range > max_range) return;
  // A sonar echo comes from the nearest reflector anywhere in the cone, not only on its axis:
  // a known obstacle (a door's jamb, a wall met obliquely) at that range within the cone
  // explains it. Placed on the axis it would be a phantom in free space beside the jamb.
  if (ArcMeetsKnown(from, angle, range, half_cone)) return;
  int ix, iy;
  if (!CellOf(from + range * dir, &ix, &iy)) return;
  const std::size_t index = Index(ix, iy);
  if (flags_[index] & (kKnown | kBlocked | kDoor | kOutside)) return;
  score_[index] = static_cast<std::int8_t>(std::min(p_.max_score, score_[index] + hit));
  if (half_cone > 0.0) {  // a sonar's: the fusion fits walls and corners to the latest echoes
    std::vector<SonarEcho>& heard = heard_[index];
    const SonarEcho e{from, angle, range, half_cone};
    if (heard.size() < static_cast<std::size_t>(p_.echoes_per_cell)) {
      heard.push_back(e);
    } else {
      heard[echoes_[index].n % heard.size()] = e;
    }
  }
  echoes_[index].Add(from + range * dir);
  if (score_[index] >= p_.confirm_score && !(flags_[index] & kConfirmed)) {
    flags_[index] |= kConfirmed;
    pending_.emplace_back(ix, iy);
  }
}

void SensorMapper::VoteDoors(const Vec2& from, double angle, double range, bool echo,
                             double max_range, double half_cone,
                             std::map<std::string, int>* ballot) {
  if (!sense_doors_ || !have_map_) return;
  const Vec2 dir(std::cos(angle), std::sin(angle));
  for (const DoorZone& z : doors_) {
    const double len = z.opening.Length();
    if (len <= 2.0 * d_.end_margin_m) continue;
    const Vec2 u = z.opening.Direction();
    if (spott_map::DistancePointSegment(from, z.opening) > d_.range_m) continue;
    const Vec2 normal(-u.y(), u.x());
    const double incidence = std::acos(std::min(1.0, std::abs(normal.dot(dir))));
    // Oblique: a leaf would not echo a sonar's pulse (specular); a profile's ray it would.
    if (incidence > (half_cone > 0.0 ? d_.normal_angle_rad : d_.profile_normal_angle_rad)) continue;
    const spott_map::Segment ray{from, from + d_.range_m * dir};
    const auto x = spott_map::SegmentIntersection(ray, z.opening);
    if (!x) continue;
    const double t = (*x - from).norm();
    if (t < 0.05 || t > std::min(d_.range_m, max_range)) continue;
    // The whole cone between the jambs (measured along the opening).
    const double margin = d_.end_margin_m + t * std::tan(half_cone) / std::cos(incidence);
    const double along = (*x - z.opening.a).dot(u);
    if (along < margin || along > len - margin) continue;
    const bool leaf_sure =
        along >= margin + d_.pose_error_m && along <= len - margin - d_.pose_error_m;
    // The way to the opening must be clear of known obstacles (not through a wall).
    bool clear = true;
    for (double s = 0.05; s < t - 0.1 && clear; s += 0.5 * p_.cell_m) {
      const Vec2 q = from + s * dir;
      int ix, iy;
      if (!CellOf(q, &ix, &iy)) {
        clear = false;
      } else if (flags_[Index(ix, iy)] & kBlocked) {
        clear = false;
      }
    }
    if (!clear) continue;
    int vote = 0;
    if (echo && std::abs(range - t) <= d_.match_m) {
      if (!leaf_sure) continue;  // the leaf, or the wall beside it
      vote = 1;                  // the leaf
    } else if ((echo && range > t + d_.beyond_m) || !echo) {
      vote = -1;  // through the opening (a leaf this square on would have echoed)
    }
    if (vote == 0) continue;
    if (ballot) {  // counted once per reading by the caller
      (*ballot)[z.id] += vote;
      continue;
    }
    int& v = door_votes_[z.id];
    v = std::clamp(v + vote, -d_.max_votes, d_.max_votes);
  }
}

void SensorMapper::AddRing(const RangeRing& ring, const Pose2& robot) {
  if (!have_map_) return;
  rings_ = true;
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  for (std::size_t i = 0; i < ring.mounts.size() && i < ring.ranges.size(); ++i) {
    const double r = ring.ranges[i];
    if (!std::isfinite(r)) continue;
    const Pose2& m = ring.mounts[i];
    const Vec2 from(robot.x + c * m.x - s * m.y, robot.y + s * m.x + c * m.y);
    const double angle = robot.yaw + m.yaw;
    const bool echo = r < ring.max_range_m - 1e-3;
    VoteDoors(from, angle, r, echo, ring.max_range_m, 0.5 * ring.field_of_view_rad);
    if (echo && r <= ring.min_range_m + p_.sonar_min_margin_m) continue;  // clamped reading
    Beam(from, angle, r, echo, p_.sonar_max_range_m, p_.sonar_hit_score,
         0.5 * ring.field_of_view_rad);
  }
}

void SensorMapper::AddPoints(const Vec2& origin, const std::vector<Vec2>& points,
                             const Pose2& robot) {
  if (!have_map_) return;
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  const auto to_map = [&](const Vec2& b) {
    return Vec2(robot.x + c * b.x() - s * b.y(), robot.y + s * b.x() + c * b.y());
  };
  const Vec2 from = to_map(origin);
  // A profile whose points near the map's features mostly miss them (0.25-0.6 m off) was taken
  // from a wrong pose: mapped, every wall it saw would come back as a new one beside it, and a
  // hallway's walls so doubled cut it. Such a profile maps nothing and votes on no door.
  if (p_.near_miss_m > p_.known_tolerance_m) {
    int on = 0, off = 0;
    for (const Vec2& p : points) {
      int ix, iy;
      if (!CellOf(to_map(p), &ix, &iy)) continue;
      const std::uint8_t f = flags_[Index(ix, iy)];
      if (f & kDoor) continue;  // a leaf the map does not know of is no pose error
      if (f & (kKnown | kOwn)) {
        ++on;
      } else if (f & kNear) {
        ++off;
      }
    }
    if (off >= p_.near_miss_points && off > on) {
      ++profiles_refused_;
      return;
    }
  }
  // A profile's many samples may cross one opening: it is one vote per door (its samples'
  // majority), as a sonar transducer's reading is; else a single profile decided a door.
  std::map<std::string, int> ballot;
  for (const Vec2& p : points) {
    const Vec2 q = to_map(p);
    const Vec2 d = q - from;
    const double r = d.norm();
    if (!std::isfinite(r) || r < 1e-3) continue;
    const double angle = std::atan2(d.y(), d.x());
    VoteDoors(from, angle, r, true, p_.range_finder_max_range_m, 0.0, &ballot);
    Beam(from, angle, r, true, p_.range_finder_max_range_m, p_.range_finder_hit_score, 0.0);
  }
  for (const auto& [id, sum] : ballot) {
    if (sum == 0) continue;
    int& v = door_votes_[id];
    v = std::clamp(v + (sum > 0 ? 1 : -1), -d_.max_votes, d_.max_votes);
  }
}

void SensorMapper::Forget() {
  std::fill(score_.begin(), score_.end(), 0);
  std::fill(echoes_.begin(), echoes_.end(), EchoMean{});
  heard_.clear();
  for (std::uint8_t& f : flags_) f &= static_cast<std::uint8_t>(~kConfirmed);
  pending_.clear();
  for (auto& [id, votes] : door_votes_) votes = 0;
  reseed_ = true;
}

void SensorMapper::Reseed(const spott_map::MapDatabase& db) {
  // The mapper's features still in the map stand for confirmed cells again: else a cluster
  // growing beside one after Forget would not cover it, and the wall would be mapped twice.
  // Sampled between the end cells' centres (a segment reaches half a cell beyond them).
  reseed_ = false;
  for (const spott_map::MapFeature& f : db.features()) {
    if (!IsOwn(f) || f.points.empty()) continue;
    const Vec2 a = f.points.front(), b = f.points.back();
    const double length = (b - a).norm();
    const Vec2 u = length > 1e-9 ? Vec2((b - a) / length) : Vec2(1.0, 0.0);
    const double inset = std::min(0.5 * p_.cell_m, 0.5 * length);
    const int n = static_cast<int>(std::ceil((length - 2.0 * inset) / (0.5 * p_.cell_m)));
    for (int i = 0; i <= n; ++i) {
      const Vec2 q = a + (inset + (length - 2.0 * inset) * (n > 0 ? double(i) / n : 0.0)) * u;
      int ix, iy;
      if (!CellOf(q, &ix, &iy)) continue;
      const std::size_t k = Index(ix, iy);
      if (flags_[k] & kConfirmed) continue;
      flags_[k] |= kConfirmed;
      score_[k] = static_cast<std::int8_t>(std::max<int>(score_[k], p_.confirm_score));
      echoes_[k] = EchoMean{};
      echoes_[k].Add(q);
    }
  }
}

bool SensorMapper::IsOwn(const spott_map::MapFeature& f) const {
  if (f.source != spott_map::FeatureSource::kSensed) return false;
  if (f.type != spott_map::FeatureType::kLineSegment && f.type != spott_map::FeatureType::kPoint)
    return false;
  const auto it = f.attributes.find("sensor");
  return it != f.attributes.end() && it->second == sensor_;
}

SensedBatch SensorMapper::Take(const spott_map::MapDatabase& db) {
  SensedBatch batch;
  if (!have_map_) return batch;
  if (reseed_) Reseed(db);  // Forget() ran and no map change has come since
  const double tol = p_.known_tolerance_m;
  // A cell another feature explains (another sensor's, a recognised object, a contact) is that
  // feature's: the map holds it already.
  const auto explained = [&](const Vec2& c) {
    for (const spott_map::MapFeature* f : db.FeaturesIn({c - Vec2(tol, tol), c + Vec2(tol, tol)}))
      if (!IsOwn(*f) && f->DistanceTo(c) <= tol) return true;
    return false;
  };
  const auto centre = [&](std::size_t i) -> Vec2 {
    return origin_ + p_.cell_m * Vec2(i % width_ + 0.5, i / width_ + 0.5);
  };
  // Each newly confirmed cell's cluster: every confirmed cell within cluster_gap_m of another,
  // old ones included. The cluster is fused anew and replaces the mapper's features it covers,
  // so a wall confirmed over many readings ends as one segment, refined as evidence comes.
  const double gap = rings_ ? p_.echo_cluster_gap_m : p_.cluster_gap_m;
  const int reach = static_cast<int>(std::ceil(gap / p_.cell_m - 1e-9));
  std::unordered_set<std::size_t> visited;
  std::vector<std::string> replaced;
  for (const auto& [sx, sy] : pending_) {
    const std::size_t seed = Index(sx, sy);
    if (visited.count(seed)) continue;
    std::vector<std::size_t> cluster;
    std::deque<std::size_t> queue{seed};
    visited.insert(seed);
    while (!queue.empty()) {
      const std::size_t k = queue.front();
      queue.pop_front();
      if (explained(centre(k))) continue;
      cluster.push_back(k);
      const int kx = static_cast<int>(k % width_), ky = static_cast<int>(k / width_);
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const int x = kx + dx, y = ky + dy;
          if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
          if (p_.cell_m * std::hypot(dx, dy) > gap + 1e-9) continue;
          const std::size_t j = Index(x, y);
          if (!(flags_[j] & kConfirmed) || visited.count(j)) continue;
          visited.insert(j);
          queue.push_back(j);
        }
      }
    }
    if (cluster.empty()) continue;
    std::vector<Vec2> cells;
    std::vector<std::vector<SonarEcho>> heard;  // each cell's sonar echoes
    bool any_heard = false;
    spott_map::Box box{centre(cluster[0]), centre(cluster[0])};
    std::unordered_set<std::size_t> members(cluster.begin(), cluster.end());
    for (const std::size_t k : cluster) {
      // Where its echoes fell, not the cell's centre: a wall's echoes straddle two rows of
      // cells, and a fit through the centres tilted short segments by up to 14 degrees.
      cells.push_back(echoes_[k].n > 0 ? echoes_[k].Mean() : centre(k));
      const auto it = heard_.find(k);
      heard.push_back(it != heard_.end() ? it->second : std::vector<SonarEcho>{});
      any_heard = any_heard || !heard.back().empty();
      box.min = box.min.cwiseMin(cells.back());
      box.max = box.max.cwiseMax(cells.back());
    }
    // The mapper's features that this cluster's cells cover (every sample of them within a
    // cell and the residual of a member) were fused from its cells before: replaced.
    const double cover = 0.75 * p_.cell_m + p_.segment_residual_m;
    const auto covered = [&](const Vec2& q) {
      int qx, qy;
      if (!CellOf(q, &qx, &qy)) return false;
      const int r = static_cast<int>(std::ceil(cover / p_.cell_m));
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int x = qx + dx, y = qy + dy;
          if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
          const std::size_t j = Index(x, y);
          if (members.count(j) && (centre(j) - q).norm() <= cover) return true;
        }
      }
      return false;
    };
    std::vector<spott_map::MapFeature> fused = FuseIntoSegments(
        cells, p_.segment_residual_m, p_.cell_m, any_heard ? &heard : nullptr, p_.echo_fit);
    // ... or the features fused now (the echoes' reflections lie off the cells: a wall's cells
    // are its echoes' axis points).
    const auto renewed = [&](const Vec2& q) {
      for (const spott_map::MapFeature& f : fused)
        if (f.DistanceTo(q) <= cover) return true;
      return false;
    };
    for (const spott_map::MapFeature& f : fused) {
      const spott_map::Box b = f.Bounds();
      box.min = box.min.cwiseMin(b.min);
      box.max = box.max.cwiseMax(b.max);
    }
    for (const spott_map::MapFeature* f :
         db.FeaturesIn({box.min - Vec2::Constant(cover), box.max + Vec2::Constant(cover)})) {
      if (!IsOwn(*f) || f->points.empty()) continue;
      bool all = true;
      const Vec2 a = f->points.front(), b = f->points.back();
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * p_.cell_m))));
      for (int i = 0; i <= n && all; ++i) {
        const Vec2 q = a + (b - a) * (double(i) / n);
        all = covered(q) || renewed(q);
      }
      if (all) replaced.push_back(f->id);
    }
    for (spott_map::MapFeature& f : fused) {
      f.source = spott_map::FeatureSource::kSensed;
      f.attributes["sensor"] = sensor_;
      batch.features.push_back(std::move(f));
    }
  }
  pending_.clear();
  std::sort(replaced.begin(), replaced.end());
  replaced.erase(std::unique(replaced.begin(), replaced.end()), replaced.end());
  batch.replaced = std::move(replaced);
  // Door states: a door whose net votes decide a state the map does not have.
  if (sense_doors_) {
    for (const spott_map::Door& door : db.graph().doors()) {
      if (door.kind != spott_map::DoorKind::kDoor) continue;
      auto it = door_votes_.find(door.id);
      if (it == door_votes_.end()) continue;
      if (it->second >= d_.votes && door.state != spott_map::DoorState::kClosed) {
        batch.doors.emplace_back(door.id, spott_map::DoorState::kClosed);
      } else if (it->second <= -d_.votes && door.state != spott_map::DoorState::kOpen) {
        batch.doors.emplace_back(door.id, spott_map::DoorState::kOpen);
      }
    }
  }
  return batch;
}

namespace {

// A group's principal axis through its mean, its extent along the axis and its largest distance
// from the axis.
struct AxisFit {
  Vec2 mean, axis;
  double tmin = 0, tmax = 0, worst = 0;
};

using Group = std::vector<std::size_t>;  // indices into the cells

AxisFit FitAxis(const std::vector<Vec2>& cells, const Group& g) {
  AxisFit f;
  f.mean = Vec2::Zero();
  for (const std::size_t i : g) f.mean += cells[i];
  f.mean /= static_cast<double>(g.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const std::size_t i : g) cov += (cells[i] - f.mean) * (cells[i] - f.mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  f.axis = eig.eigenvectors().col(1).normalized();  // the largest eigenvalue's
  const Vec2 normal(-f.axis.y(), f.axis.x());
  f.tmin = 1e300;
  f.tmax = -1e300;
  for (const std::size_t i : g) {
    const double t = (cells[i] - f.mean).dot(f.axis);
    f.tmin = std::min(f.tmin, t);
    f.tmax = std::max(f.tmax, t);
    f.worst = std::max(f.worst, std::abs((cells[i] - f.mean).dot(normal)));
  }
  return f;
}

// Split: recursively at the median along the principal axis until each group lies within
// `residual` of its axis (`residual` counts from the cells' squares, not their centres: echoes
// of one wall spread over two or three rows of cells).
void Split(const std::vector<Vec2>& cells, const Group& g, double residual, int depth,
           std::vector<Group>& out) {
  if (g.size() == 1) {
    out.push_back(g);
    return;
  }
  const AxisFit fit = FitAxis(cells, g);
  if (fit.worst <= residual || depth >= 8) {
    out.push_back(g);
    return;
  }
  std::vector<double> t(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) t[k] = (cells[g[k]] - fit.mean).dot(fit.axis);
  std::vector<double> sorted = t;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  Group low, high;
  for (std::size_t k = 0; k < g.size(); ++k) (t[k] < median ? low : high).push_back(g[k]);
  if (low.empty() || high.empty()) {  // all on one side of the median: split in halves
    low.assign(g.begin(), g.begin() + g.size() / 2);
    high.assign(g.begin() + g.size() / 2, g.end());
  }
  Split(cells, low, residual, depth + 1, out);
  Split(cells, high, residual, depth + 1, out);
}

spott_map::MapFeature SegmentOrPoint(const Vec2& a, const Vec2& b, double cell_m) {
  if ((b - a).norm() < 0.9 * cell_m) return spott_map::MakePoint("", 0.5 * (a + b), "");
  return spott_map::MakeSegment("", spott_map::Segment{a, b}, "", 0.0);
}

// An echo placed on a wall's line: where it reflected (t along the line), the range the wall
// predicts, the echo (null: a cell without echoes, an earlier feature's sample).
struct Foot {
  double t = 0.0, predicted = 0.0;
  const SonarEcho* echo = nullptr;
};

// Where a wall ends, and how many of its echoes the end's edge explains better. Beyond a wall's
// end (a doorway's jamb) a transducer still hears it, from the edge, while the edge is in its
// cone: the range is then the edge's distance, up to range (1 / cos(half cone) - 1) longer than
// the wall's foot, less than the noise each (the doorway "larger-than-life", SPOTT section V),
// but many echoes together tell it. `side` +1: the end at the larger t, -1: the other. The end
// is the t (among the echoes' feet near that end) with the least squared residuals, echoes on
// the wall's side of it heard from the wall, those beyond it from the edge there (an echo whose
// cone does not hold the edge cannot lie beyond). Cells without echoes stay on the wall.
struct WallEnd {
  double t = 0.0;
  int edge_echoes = 0;
};
WallEnd FindWallEnd(const std::vector<Foot>& run, const Vec2& foot, const Vec2& u, double side) {
  // The run's feet from this end inwards, as far as an edge at the end can be heard.
  std::vector<const Foot*> near;
  const Foot& last = side > 0 ? run.back() : run.front();
  double reach = 0.0;
  for (std::size_t n = 0; n < run.size(); ++n) {
    const Foot& f = side > 0 ? run[run.size() - 1 - n] : run[n];
    if (f.echo) reach = std::max(reach, f.echo->range * std::tan(f.echo->half_cone + 0.05));
    if (side * (last.t - f.t) > reach) break;
    near.push_back(&f);
  }
  WallEnd best{last.t, 0};
  double best_cost = 1e300;
  for (std::size_t c = 0; c < near.size(); ++c) {
    const double te = near[c]->t;  // the end at this foot: near[0 .. c-1] lie beyond it
    const Vec2 edge = foot + te * u;
    double cost = 0.0;
    int beyond = 0;
    for (std::size_t k = 0; k < near.size() && cost < best_cost; ++k) {
      const Foot& f = *near[k];
      if (!f.echo) {
        if (k < c) cost = 1e300;  // an earlier feature reached there: the wall does
        continue;
      }
      if (k >= c) {
        cost += std::pow(f.echo->range - f.predicted, 2);
        continue;
      }
      const std::optional<double> r = CornerResidual(*f.echo, edge);
      if (!r) {
        cost = 1e300;
        continue;
      }
      cost += *r * *r;
      ++beyond;
    }
    if (cost < best_cost) {
      best_cost = cost;
      best = {te, beyond};
    }
  }
  return best;
}

// A cluster fused from its sonar echoes (sonar_echo_fit.h), one reflector at a time (sequential
// RANSAC): each group of cells proposes the wall and the corner that explain its echoes not
// explained yet; the proposal that explains the cluster's remaining echoes best (MSAC cost; a
// corner must cost under 0.7 of the wall: a wall's echoes over a short stretch fit a point too)
// is kept and its echoes taken out, until none explains 3. A wall's segments span where its
// echoes reflected (not their axis points, which run on past its end), cut where they leave a
// gap; a wall whose direction its echoes do not fix is kept as points. Cells without echoes (an
// earlier feature's samples, after Forget) extend a wall they lie on.
void FuseFromEchoes(const std::vector<Vec2>& cells, const std::vector<Group>& groups,
                    const std::vector<std::vector<SonarEcho>>& echoes, double cell_m,
                    const EchoFitParameters& p, std::vector<spott_map::MapFeature>& out) {
  std::vector<SonarEcho> all;
  std::vector<std::size_t> owner;  // each echo's group
  std::vector<Vec2> bare;
  std::vector<AxisFit> fits;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    fits.push_back(FitAxis(cells, groups[gi]));
    for (const std::size_t i : groups[gi]) {
      if (echoes[i].empty()) bare.push_back(cells[i]);
      for (const SonarEcho& e : echoes[i]) {
        all.push_back(e);
        owner.push_back(gi);
      }
    }
  }
  std::vector<bool> used(all.size(), false), bare_used(bare.size(), false);
  struct Proposal {
    bool wall = false;
    EchoLine line;
    EchoPoint corner;
    std::vector<std::size_t> inliers;  // into `all`
    double cost = 1e300;
  };
  // An echo's range residual against a wall (1e9: the wall gives that transducer no echo).
  const auto wall_residual = [&p](const SonarEcho& e, const EchoLine& line) {
    const auto predicted = PredictEcho(e, line.normal, line.offset, p.max_incidence_rad);
    return predicted ? std::abs(predicted->range - e.range) : 1e9;
  };
  for (std::size_t round = 0; round < 2 * groups.size() + 2; ++round) {
    Proposal best;
    for (std::size_t gi = 0; gi < groups.size(); ++gi) {
      std::vector<SonarEcho> local;
      Vec2 sensors = Vec2::Zero();
      for (std::size_t k = 0; k < all.size(); ++k) {
        if (used[k] || owner[k] != gi) continue;
        local.push_back(all[k]);
        sensors += all[k].from;
      }
      if (local.size() < 3) continue;
      sensors /= static_cast<double>(local.size());
      Vec2 n0(-fits[gi].axis.y(), fits[gi].axis.x());
      if (n0.dot(sensors - fits[gi].mean) < 0) n0 = -n0;  // toward the transducers
      Proposal wall, corner;
      wall.wall = true;
      wall.line = FitEchoLine(local, std::atan2(n0.y(), n0.x()), 0.4, p);
      corner.corner = FitEchoPoint(local, fits[gi].mean, p);
      wall.cost = corner.cost = 0.0;
      for (std::size_t k = 0; k < all.size(); ++k) {
        if (used[k]) continue;
        const SonarEcho& e = all[k];
        const double tol = EchoTolerance(e, p);
        const double rw = wall_residual(e, wall.line);
        wall.cost += EchoCost(rw, tol);
        if (rw <= tol) wall.inliers.push_back(k);
        const std::optional<double> at_corner = CornerResidual(e, corner.corner.at);
        const double rc = at_corner ? std::abs(*at_corner) : 1e9;
        corner.cost += EchoCost(rc, tol);
        if (rc <= tol) corner.inliers.push_back(k);
      }
      if (wall.line.inliers.empty()) wall.cost = 1e300;
      // Seen over a short stretch a wall's echoes fit a point too: a corner must then do
      // clearly better, unless the wall's direction is not fixed either.
      if (wall.line.direction_error_rad <= p.max_direction_error_rad) corner.cost /= 0.7;
      for (Proposal* c : {&corner, &wall})  // a tie (one spot heard alone): the corner
        if (c->inliers.size() >= 3 && c->cost < best.cost) best = std::move(*c);
    }
    if (best.inliers.size() < 3) break;
    if (best.wall) {
      // Refit on the whole consensus: the group proposed the wall from its own echoes, but
      // the cluster's other groups heard it too (a scan's turned beams, a wall split by the
      // cells' split/merge), and only all of them fix its direction.
      std::vector<SonarEcho> consensus;
      for (const std::size_t k : best.inliers) consensus.push_back(all[k]);
      const double phi = std::atan2(best.line.normal.y(), best.line.normal.x());
      EchoLine refit = FitEchoLine(consensus, phi, 0.1, p);
      if (!refit.inliers.empty()) {
        std::vector<std::size_t> inliers;
        for (std::size_t k = 0; k < all.size(); ++k)
          if (!used[k] && wall_residual(all[k], refit) <= EchoTolerance(all[k], p))
            inliers.push_back(k);
        if (inliers.size() >= best.inliers.size()) {
          best.line = std::move(refit);
          best.inliers = std::move(inliers);
        }
      }
    }
    for (const std::size_t k : best.inliers) used[k] = true;
    if (!best.wall) {
      out.push_back(spott_map::MakePoint("", best.corner.at, ""));
      continue;
    }
    const EchoLine& line = best.line;
    const Vec2 u(-line.normal.y(), line.normal.x());
    const Vec2 foot = line.offset * line.normal;  // a point on the line
    std::vector<Foot> feet;
    for (const std::size_t k : best.inliers) {
      const auto predicted = PredictEcho(all[k], line.normal, line.offset, p.max_incidence_rad);
      feet.push_back({(predicted->reflection - foot).dot(u), predicted->range, &all[k]});
    }
    for (std::size_t b = 0; b < bare.size(); ++b) {
      if (bare_used[b] || std::abs(line.normal.dot(bare[b]) - line.offset) > 0.5 * cell_m) continue;
      bare_used[b] = true;
      feet.push_back({(bare[b] - foot).dot(u), 0.0, nullptr});
    }
    std::sort(feet.begin(), feet.end(), [](const Foot& a, const Foot& b) { return a.t < b.t; });
    const bool certain = line.direction_error_rad <= p.max_direction_error_rad;
    for (std::size_t i = 0; i < feet.size();) {
      std::size_t j = i;
      while (j + 1 < feet.size() && feet[j + 1].t - feet[j].t <= 3.0 * cell_m) ++j;
      const std::vector<Foot> run(feet.begin() + i, feet.begin() + j + 1);
      i = j + 1;
      if (!certain) {  // where it reflected is known, its direction is not: points two cells apart
        const double t0 = run.front().t, t1 = run.back().t;
        const int n = static_cast<int>(std::ceil((t1 - t0) / (2.0 * cell_m)));
        for (int k = 0; k <= n; ++k)
          out.push_back(
              spott_map::MakePoint("", foot + (t0 + (t1 - t0) * k / std::max(n, 1)) * u, ""));
        continue;
      }
      const WallEnd end = FindWallEnd(run, foot, u, +1.0);
      const WallEnd start = FindWallEnd(run, foot, u, -1.0);
      out.push_back(SegmentOrPoint(foot + start.t * u, foot + end.t * u, cell_m));
      for (const WallEnd& e : {start, end})
        if (e.edge_echoes >= 3) out.push_back(spott_map::MakePoint("", foot + e.t * u, ""));
    }
  }
}

}  // namespace

std::vector<spott_map::MapFeature> FuseIntoSegments(
    const std::vector<Vec2>& cells, double residual_m, double cell_m,
    const std::vector<std::vector<SonarEcho>>* echoes, const EchoFitParameters& echo_fit) {
  std::vector<spott_map::MapFeature> out;
  if (cells.empty()) return out;
  std::vector<Group> groups;
  const double residual = residual_m + 0.5 * cell_m;  // from a cell's centre
  Group everything(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) everything[i] = i;
  Split(cells, everything, residual, 0, groups);
  // Merge: groups whose union still lies within the residual of one axis are one line (a split
  // at the median cuts a straight run in two where another part of the cluster bent).
  for (bool merged = true; merged && groups.size() > 1;) {
    merged = false;
    for (std::size_t i = 0; i < groups.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < groups.size() && !merged; ++j) {
        Group both = groups[i];
        both.insert(both.end(), groups[j].begin(), groups[j].end());
        if (FitAxis(cells, both).worst > residual) continue;
        groups[i] = std::move(both);
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
    }
  }
  std::vector<Group> heard_groups;  // groups with sonar echoes: fused from them together
  for (const Group& g : groups) {
    bool heard = false;
    if (echoes)
      for (const std::size_t i : g) heard = heard || !(*echoes)[i].empty();
    if (heard) {
      heard_groups.push_back(g);
      continue;
    }
    const AxisFit fit = FitAxis(cells, g);
    // The cells' extent along the axis, to the outer edges of the end cells.
    if (g.size() == 1 || fit.tmax - fit.tmin < 0.9 * cell_m) {
      out.push_back(spott_map::MakePoint("", fit.mean, ""));
      continue;
    }
    const spott_map::Segment s{fit.mean + (fit.tmin - 0.5 * cell_m) * fit.axis,
                               fit.mean + (fit.tmax + 0.5 * cell_m) * fit.axis};
    out.push_back(spott_map::MakeSegment("", s, "", 0.0));
  }
  if (!heard_groups.empty()) FuseFromEchoes(cells, heard_groups, *echoes, cell_m, echo_fit, out);
  return out;
}

}  // namespace spott_tr_plus::controller
