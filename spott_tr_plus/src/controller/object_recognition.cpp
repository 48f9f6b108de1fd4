#include "spott_tr_plus/controller/object_recognition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <Eigen/Dense>

#include "violation.h"

namespace spott_tr_plus::controller {

namespace {

using spott_map::FeatureType;

// Unsigned arithmetic: a negative index shifted left is undefined (the fuzzer found it); the
// indices are clamped so that any finite point has one.
std::int64_t CellKey(const Vec2& p, double cell) {
  const auto index = [cell](double v) {
    return static_cast<std::uint64_t>(
        static_cast<std::int64_t>(std::clamp(std::floor(v / cell), -2e9, 2e9)));
  };
  return static_cast<std::int64_t>((index(p.x()) << 32) ^ (index(p.y()) & 0xffffffffULL));
}

double BoxDiagonal(const std::vector<Vec2>& points) {
  if (points.empty()) return 0.0;
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// Kasa's algebraic circle fit, in coordinates centred on the points' mean (well conditioned).
bool FitCircle(const std::vector<Vec2>& points, Vec2* centre, double* radius) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const Vec2& q : points) {
    const Vec2 p = q - mean;
    const Eigen::Vector3d row(p.x(), p.y(), 1.0);
    a += row * row.transpose();
    b -= row * p.squaredNorm();
  }
  const Eigen::Vector3d s = a.ldlt().solve(b);
  if (!s.allFinite()) return false;
  const Vec2 c(-s(0) / 2, -s(1) / 2);
  const double r2 = c.squaredNorm() - s(2);
  if (!(r2 > 0)) return false;
  *centre = c + mean;
  *radius = std::sqrt(r2);
  return true;
}

// The angle the points span around `c`: 2 pi less the widest gap between neighbours.
double ArcSpan(const std::vector<Vec2>& points, const Vec2& c) {
  std::vector<double> a;
  a.reserve(points.size());
  for (const Vec2& p : points) a.push_back(std::atan2(p.y() - c.y(), p.x() - c.x()));
  std::sort(a.begin(), a.end());
  double gap = a.front() + 2 * M_PI - a.back();
  for (std::size_t i = 1; i < a.size(); ++i) gap = std::max(gap, a[i] - a[i - 1]);
  return 2 * M_PI - gap;
}

}  // namespace

std::vector<ObjectModel> DefaultObjectModels() {
  // The bands hold the objects of the shipped worlds with what one view shows of them (a chair's
  // single face, a desk's short end): sides are lower bounds, heights are measured.
  return {
      {"cylinder", FeatureType::kGeonCylinder, true, 0.2, 1.2, 1.2, 0.3, 1.6, 0.0},
      // A chair's seat is about square; a desk is about 0.8 m deep.
      {"chair", FeatureType::kGeonCuboid, false, 0.3, 0.75, 0.75, 0.8, 1.05, 0.5},
      // Below a chair's height a part of a desk is a desk (one seen behind a chair, or in
      // passing, shows 0.4-0.7 m of its face); at a chair's height only a longer side tells.
      {"desk", FeatureType::kGeonCuboid, false, 0.4, 3.2, 1.5, 0.65, 0.8, 0.8, 0.0, true},
      {"desk", FeatureType::kGeonCuboid, false, 0.75, 3.2, 1.5, 0.8, 0.95, 0.8, 0.0, true},
      // Taller than the heads see over: a thin one is a partition, a deeper one a shelf.
      // (the lab's 0.08 m partition measured 0.09-0.2 m thick from the moving robot).
      {"partition", FeatureType::kGeonCuboid, false, 1.0, 3.5, 0.25, 1.2, 0.0, 0.0},
      {"shelf", FeatureType::kGeonCuboid, false, 0.8, 3.0, 0.8, 1.3, 0.0, 0.0, 0.25},
      // Lower than a desk: a desk seen in part (a side shorter than a desk's) is not a cuboid.
      {"cuboid", FeatureType::kGeonCuboid, false, 0.2, 2.0, 2.0, 0.2, 0.65, 0.0},
  };
}

std::vector<std::string> ValidateParameters(const RecognitionParameters& p) {
  std::vector<std::string> v;
  if (!(p.cell_m >= 0.005 && p.cell_m <= 0.2))
    v.push_back(Violation("cell_m", "in [0.005, 0.2]", p.cell_m));
  if (!(p.cluster_gap_m > p.cell_m && std::isfinite(p.cluster_gap_m)))
    v.push_back(Violation("cluster_gap_m", "> cell_m", p.cluster_gap_m));
  if (!(p.known_tolerance_m >= 0 && std::isfinite(p.known_tolerance_m)))
    v.push_back(Violation("known_tolerance_m", ">= 0", p.known_tolerance_m));
  if (!std::isfinite(p.floor_m)) v.push_back(Violation("floor_m", "finite", p.floor_m));
  if (!(p.max_range_m > 0 && std::isfinite(p.max_range_m)))
    v.push_back(Violation("max_range_m", "> 0", p.max_range_m));
  if (!(p.top_jump_m > 0 && std::isfinite(p.top_jump_m)))
    v.push_back(Violation("top_jump_m", "> 0", p.top_jump_m));
  if (!(p.top_flat_m >= 0 && std::isfinite(p.top_flat_m)))
    v.push_back(Violation("top_flat_m", ">= 0", p.top_flat_m));
  if (p.min_points < 3) v.push_back(Violation("min_points", ">= 3", p.min_points));
  if (p.min_vertical_points < 3 || p.min_vertical_points > p.min_points)
    v.push_back(Violation("min_vertical_points", "in [3, min_points]", p.min_vertical_points));
  if (p.min_cell_hits < 1 || p.min_cell_hits > 3)
    v.push_back(Violation("min_cell_hits", "in [1, 3]", p.min_cell_hits));
  if (!(p.top_join_m >= p.cluster_gap_m && p.top_join_m <= p.max_extent_m))
    v.push_back(Violation("top_join_m", "in [cluster_gap_m, max_extent_m]", p.top_join_m));
  if (!(p.vertical_block_m >= p.cell_m && p.vertical_block_m <= p.cluster_gap_m))
    v.push_back(Violation("vertical_block_m", "in [cell_m, cluster_gap_m]", p.vertical_block_m));
  if (p.min_views < 1) v.push_back(Violation("min_views", ">= 1", p.min_views));
  if (!(p.growth_m > 0 && std::isfinite(p.growth_m)))
    v.push_back(Violation("growth_m", "> 0", p.growth_m));
  if (p.stable_views < 0) v.push_back(Violation("stable_views", ">= 0", p.stable_views));
  if (p.quiet_profiles < 1) v.push_back(Violation("quiet_profiles", ">= 1", p.quiet_profiles));
  if (!(p.circle_residual_m >= 0 && std::isfinite(p.circle_residual_m)))
    v.push_back(Violation("circle_residual_m", ">= 0", p.circle_residual_m));
  if (!(p.min_arc_rad > 0 && p.min_arc_rad <= 2 * M_PI))
    v.push_back(Violation("min_arc_rad", "in (0, 2 pi]", p.min_arc_rad));
  if (!(p.max_extent_m > 0 && std::isfinite(p.max_extent_m)))
    v.push_back(Violation("max_extent_m", "> 0", p.max_extent_m));
  if (p.look_views < 0) v.push_back(Violation("look_views", ">= 0", p.look_views));
  if (!(p.look_below_top_m > 0 && p.look_below_top_m <= 1))
    v.push_back(Violation("look_below_top_m", "in (0, 1]", p.look_below_top_m));
  if (!(p.wall_depth_m >= 0 && p.wall_depth_m <= p.max_extent_m))
    v.push_back(Violation("wall_depth_m", "in [0, max_extent_m]", p.wall_depth_m));
  return v;
}

namespace {

// The rectangle around `points` whose sides they lie closest to; `*rms` their RMS distance from
// its nearest side.
Footprint FitRectangle(const std::vector<Vec2>& points, double* rms) {
  Footprint fp;
  // The rectangle over directions of a quarter turn (its sides repeat after).
  double best = 1e300;
  for (int k = 0; k < 90; ++k) {
    const double a = k * M_PI / 180.0;
    const Vec2 u(std::cos(a), std::sin(a)), w(-u.y(), u.x());
    double lo_u = 1e300, hi_u = -1e300, lo_w = 1e300, hi_w = -1e300;
    for (const Vec2& q : points) {
      lo_u = std::min(lo_u, q.dot(u));
      hi_u = std::max(hi_u, q.dot(u));
      lo_w = std::min(lo_w, q.dot(w));
      hi_w = std::max(hi_w, q.dot(w));
    }
    // The faces seen lie on the rectangle's sides: the direction whose box leaves the echoes
    // closest to its sides (an L of two faces has the same area boxed along its diagonal).
    double off = 0.0, sq = 0.0;
    for (const Vec2& q : points) {
      const double du = q.dot(u), dw = q.dot(w);
      const double d = std::min({du - lo_u, hi_u - du, dw - lo_w, hi_w - dw});
      off += d;
      sq += d * d;
    }
    const double su = hi_u - lo_u, sw = hi_w - lo_w;
    const double cost = off + 1e-6 * su * sw;  // ties (a straight face): the smaller box
    if (cost >= best) continue;
    best = cost;
    *rms = std::sqrt(sq / static_cast<double>(points.size()));
    fp.centre = u * (lo_u + hi_u) / 2 + w * (lo_w + hi_w) / 2;
    fp.long_m = std::max(su, sw);
    fp.short_m = std::min(su, sw);
    fp.yaw = su >= sw ? a : spott_map::NormalizeAngle(a + M_PI / 2);
  }
  return fp;
}

}  // namespace

Footprint FitFootprint(const std::vector<Vec2>& points, const RecognitionParameters& p) {
  if (points.empty()) return Footprint{};
  double rectangle_rms = 0.0;
  const Footprint rectangle = FitRectangle(points, &rectangle_rms);
  Vec2 c;
  double r = 0.0;
  if (points.size() < 5 || !FitCircle(points, &c, &r) || 2 * r > p.max_extent_m) return rectangle;
  double sq = 0.0;
  for (const Vec2& q : points) sq += std::pow((q - c).norm() - r, 2);
  const double rms = std::sqrt(sq / static_cast<double>(points.size()));
  // Round only when the arc fits better than the rectangle's sides: a chair seen across its
  // corner (two short faces) lies on an arc within a centimetre too (chair_lab_2, a cylinder).
  if (rms > p.circle_residual_m || rms >= rectangle_rms || ArcSpan(points, c) < p.min_arc_rad)
    return rectangle;
  Footprint fp;
  fp.round = true;
  fp.centre = c;
  fp.radius_m = r;
  fp.long_m = fp.short_m = 2 * r;
  return fp;
}

namespace {

// `fp` grown away from `viewer` to the face of a CAD wall parallel behind it (within 5 degrees,
// across from the footprint's middle) when that face lies within `max_depth` of the footprint's
// near side: the thing stands with its back to the wall.
void GrowToWallBehind(Footprint* fp, const Vec2& viewer, const spott_map::MapDatabase& map,
                      double max_depth) {
  if (fp->round || max_depth <= 0) return;
  const Vec2 along(std::cos(fp->yaw), std::sin(fp->yaw));
  Vec2 away(-along.y(), along.x());
  if (away.dot(fp->centre - viewer) < 0) away = -away;
  const Vec2 back = fp->centre + away * (fp->short_m / 2);
  const double reach = fp->long_m / 2 + max_depth;
  double gap = std::numeric_limits<double>::infinity();
  for (const spott_map::MapFeature* f :
       map.FeaturesIn(spott_map::Box{back, back}.Inflated(reach))) {
    if (f->source != spott_map::FeatureSource::kCad ||
        f->type != spott_map::FeatureType::kLineSegment || f->points.size() < 2)
      continue;
    const spott_map::Segment wall{f->points[0], f->points[1]};
    const Vec2 d = wall.Direction();
    if (std::abs(d.dot(away)) > std::sin(5.0 * M_PI / 180.0)) continue;
    const double t = (back - wall.a).dot(d);
    if (t < 0 || t > wall.Length()) continue;
    const double g = (wall.a - back).dot(away) - f->size_y / 2;
    if (g >= -0.05 && g + fp->short_m <= max_depth) gap = std::min(gap, std::max(g, 0.0));
  }
  if (!std::isfinite(gap)) return;
  fp->centre += away * (gap / 2);
  fp->short_m += gap;
  if (fp->short_m > fp->long_m) {
    std::swap(fp->short_m, fp->long_m);
    fp->yaw = spott_map::NormalizeAngle(fp->yaw + M_PI / 2);
  }
}

}  // namespace

const ObjectModel* Classify(const ObjectCandidate& c, const RecognitionParameters& p, Footprint* fp,
                            bool out_of_view, const spott_map::MapDatabase* map) {
  if (c.views < p.min_views || (c.stable < p.stable_views && !out_of_view)) return nullptr;
  const std::vector<Vec2> cells = c.Confirmed(p);
  if (static_cast<int>(cells.size()) < (c.horizontal ? p.min_points : p.min_vertical_points))
    return nullptr;
  *fp = FitFootprint(cells, p);
  if (fp->long_m > p.max_extent_m) return nullptr;
  // Only a thing whose top was not seen: a chair beside a wall is no deeper for it.
  if (map && !c.top_m) GrowToWallBehind(fp, c.viewer, *map, p.wall_depth_m);
  for (const ObjectModel& m : p.models) {
    if (m.round != fp->round) continue;
    if (fp->long_m < m.min_long_m || fp->long_m > m.max_long_m || fp->short_m > m.max_short_m ||
        fp->short_m < m.min_short_m)
      continue;
    // A face met at the heads' height but never seen whole may go on beyond the profiles'
    // field; of the things taller than the heads see over, sides are lower bounds anyway.
    if (m.max_height_m > 0 && c.horizontal && !c.face_whole && !m.open_long) continue;
    if (m.max_height_m > 0) {
      if (!c.top_m || *c.top_m < m.min_height_m || *c.top_m > m.max_height_m) continue;
    } else if (c.height_seen_m < m.min_height_m) {
      continue;
    }
    return &m;
  }
  return nullptr;
}

ObjectRecognizer::ObjectRecognizer(RecognitionParameters p) : p_(std::move(p)) {}

bool ObjectRecognizer::Known(const Vec2& p,
                             const std::vector<const spott_map::MapFeature*>& near) const {
  for (const spott_map::MapFeature* f : near) {
    // The CAD map and the objects named before explain their echoes; the sensed segments do
    // not: they may be this very object's faces, mapped by the sonar a moment ago.
    if (f->source != spott_map::FeatureSource::kCad && f->label.empty()) continue;
    if (f->DistanceTo(p) <= p_.known_tolerance_m) return true;
  }
  if (db_) {
    for (const spott_map::Door& d : db_->graph().doors()) {
      if (spott_map::DistancePointSegment(p, d.opening) <= p_.known_tolerance_m) return true;
    }
  }
  return false;
}

namespace {

// Records `profile` among the newest three distinct ones in `ids`.
void Remember(std::array<std::uint64_t, 3>& ids, std::uint64_t profile) {
  if (std::find(ids.begin(), ids.end(), profile) != ids.end()) return;
  ids = {profile, ids[0], ids[1]};
}

// The distinct profiles `ids_at` gives for the 3 x 3 grid cells of side `side` around `at`.
template <typename IdsAt>
int ProfilesAround(const Vec2& at, double side, IdsAt ids_at) {
  std::array<std::uint64_t, 27> ids{};
  std::size_t n = 0;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      const std::array<std::uint64_t, 3>* seen = ids_at(CellKey(at + side * Vec2(dx, dy), side));
      if (!seen) continue;
      for (std::uint64_t id : *seen) {
        if (id != 0 && std::find(ids.begin(), ids.begin() + n, id) == ids.begin() + n)
          ids[n++] = id;
      }
    }
  }
  return static_cast<int>(n);
}

}  // namespace

void ObjectCandidate::Hit(const Vec2& at, std::uint64_t profile, bool vertical,
                          const RecognitionParameters& p) {
  Remember(blocks[CellKey(at, p.vertical_block_m)], profile);
  const auto [it, added] = cells.emplace(CellKey(at, p.cell_m), points.size());
  if (added) {
    points.push_back(at);
    seen_by.push_back({profile, 0, 0});
    horizontal_hit.push_back(!vertical);
    return;
  }
  Remember(seen_by[it->second], profile);
  if (!vertical) horizontal_hit[it->second] = 1;
}

std::vector<Vec2> ObjectCandidate::Confirmed(const RecognitionParameters& p) const {
  const auto cell_ids = [this](std::int64_t key) -> const std::array<std::uint64_t, 3>* {
    const auto it = cells.find(key);
    return it == cells.end() ? nullptr : &seen_by[it->second];
  };
  const auto block_ids = [this](std::int64_t key) -> const std::array<std::uint64_t, 3>* {
    const auto it = blocks.find(key);
    return it == blocks.end() ? nullptr : &it->second;
  };
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int n = horizontal_hit[i] ? ProfilesAround(points[i], p.cell_m, cell_ids)
                                    : ProfilesAround(points[i], p.vertical_block_m, block_ids);
    if (n >= p.min_cell_hits) out.push_back(points[i]);
  }
  return out;
}

std::size_t ObjectRecognizer::CandidateFor(const std::vector<Vec2>& run,
                                           std::optional<double> top) {
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const ObjectCandidate& c = candidates_[i];
    // A run up a face and over a top at the height of a candidate's top is that object's part
    // within top_join_m: sparse vertical profiles meet a desk 0.1-0.8 m apart along its face.
    const bool same_top = top && c.top_m && std::abs(*c.top_m - *top) <= p_.top_flat_m;
    const double gap = same_top ? p_.top_join_m : p_.cluster_gap_m;
    const auto& pts = c.points;
    const bool near = std::any_of(run.begin(), run.end(), [&](const Vec2& q) {
      return std::any_of(pts.begin(), pts.end(),
                         [&](const Vec2& r) { return (q - r).squaredNorm() <= gap * gap; });
    });
    if (near) hits.push_back(i);
  }
  if (hits.empty()) {
    candidates_.emplace_back();
    return candidates_.size() - 1;
  }
  // The run bridges several: they were one object seen in parts.
  ObjectCandidate& keep = candidates_[hits[0]];
  for (std::size_t k = hits.size(); k-- > 1;) {
    ObjectCandidate& other = candidates_[hits[k]];
    for (std::size_t i = 0; i < other.points.size(); ++i) {
      for (std::uint64_t id : other.seen_by[i]) {
        if (id != 0) keep.Hit(other.points[i], id, !other.horizontal_hit[i], p_);
      }
    }
    keep.height_seen_m = std::max(keep.height_seen_m, other.height_seen_m);
    if (other.top_m) keep.top_m = std::max(keep.top_m.value_or(0.0), *other.top_m);
    keep.face_whole = keep.face_whole || other.face_whole;
    keep.horizontal = keep.horizontal || other.horizontal;
    keep.views = std::max(keep.views, other.views);
    keep.stable = 0;
    if (keep.label.empty()) keep.label = other.label;
    candidates_.erase(candidates_.begin() + static_cast<std::ptrdiff_t>(hits[k]));
  }
  return hits[0];
}

void ObjectRecognizer::AddProfile(const Vec3& origin, const std::vector<ProfileSample>& samples,
                                  bool vertical) {
  if (!origin.allFinite() || samples.size() < 2) return;
  ++profiles_;
  // The order along the profile: a vertical one by elevation, lowest first.
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  if (vertical) {
    const auto elevation = [&](std::size_t i) {
      const Vec3 d = samples[i].point - origin;
      return std::atan2(d.z(), d.head<2>().norm());
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return elevation(a) < elevation(b); });
  }
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const ProfileSample& s : samples) {
    if (!s.point.allFinite()) continue;
    lo = lo.cwiseMin(Vec2(s.point.head<2>()));
    hi = hi.cwiseMax(Vec2(s.point.head<2>()));
  }
  if (!(lo.x() <= hi.x())) return;
  std::vector<const spott_map::MapFeature*> near;
  if (db_) near = db_->FeaturesIn(spott_map::Box{lo, hi}.Inflated(p_.known_tolerance_m));
  std::vector<char> object(samples.size(), 0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ProfileSample& s = samples[i];
    object[i] = s.echo && s.point.allFinite() && s.point.z() >= p_.floor_m &&
                (s.point - origin).norm() <= p_.max_range_m && !Known(s.point.head<2>(), near);
  }
  // Beyond: the ray next to a run's end went on past it, by top_jump_m (an echo farther, or
  // none: its point lies at the sensor's range, which must then exceed the end's by as much).
  const auto beyond = [&](std::size_t next, const Vec3& end) {
    const ProfileSample& s = samples[next];
    if (!s.point.allFinite()) return false;
    return (s.point - origin).norm() > (end - origin).norm() + p_.top_jump_m;
  };
  std::size_t k = 0;
  while (k < order.size()) {
    if (!object[order[k]]) {
      ++k;
      continue;
    }
    std::size_t end = k + 1;  // the run: neighbours along the profile, close in space
    // Up a vertical profile the run goes on over a flat top (a desk's): the rays that pass the
    // face's edge land on the top, at its height, farther away.
    const auto joins = [&](const Vec3& a, const Vec3& b) {
      if ((b - a).norm() <= p_.cluster_gap_m) return true;
      return vertical && std::abs(b.z() - a.z()) <= p_.top_flat_m &&
             (b - a).head<2>().norm() <= p_.max_extent_m / 2;
    };
    while (end < order.size() && object[order[end]] &&
           joins(samples[order[end - 1]].point, samples[order[end]].point)) {
      ++end;
    }
    std::vector<Vec2> run;
    double top = 0.0;
    for (std::size_t j = k; j < end; ++j) {
      run.emplace_back(samples[order[j]].point.head<2>());
      top = std::max(top, samples[order[j]].point.z());
    }
    const Vec3& first = samples[order[k]].point;
    const Vec3& last = samples[order[end - 1]].point;
    const bool top_seen = vertical && end < order.size() && beyond(order[end], last);
    // Only a top below the heads is one the rays landed on (a desk's); a chair and a drum beside
    // it, both 0.9 m high, are two objects.
    const bool top_below = top_seen && top < origin.z() - p_.top_flat_m;
    ObjectCandidate& c =
        candidates_[CandidateFor(run, top_below ? std::optional<double>(top) : std::nullopt)];
    for (const Vec2& q : run) c.Hit(q, profiles_, vertical, p_);
    c.height_seen_m = std::max(c.height_seen_m, top);
    if (vertical) {
      if (top_seen) c.top_m = std::max(c.top_m.value_or(0.0), top);
    } else {
      c.horizontal = true;
      if (k > 0 && end < order.size() && beyond(order[k - 1], first) && beyond(order[end], last))
        c.face_whole = true;
    }
    c.last_profile = profiles_;
    c.viewer = origin.head<2>();
    k = end;
  }
  for (ObjectCandidate& c : candidates_) {
    if (c.last_profile != profiles_) continue;
    ++c.views;
    if (vertical) ++c.vertical_views;
    const double extent = BoxDiagonal(c.points);
    c.stable = extent > c.extent_m + p_.growth_m ? 0 : c.stable + 1;
    if (c.stable == 0) c.extent_m = extent;
  }
  // Bounded memory: the objects met longest ago and never named go first.
  constexpr std::size_t kMaxCandidates = 200;
  while (candidates_.size() > kMaxCandidates) {
    auto oldest = std::min_element(candidates_.begin(), candidates_.end(),
                                   [](const ObjectCandidate& a, const ObjectCandidate& b) {
                                     return a.last_profile < b.last_profile;
                                   });
    candidates_.erase(oldest);
  }
}

std::optional<LookTarget> ObjectRecognizer::ToLookAt(const Vec2& from) const {
  std::optional<LookTarget> best;
  double nearest = p_.max_range_m;
  for (const ObjectCandidate& c : candidates_) {
    if (!c.label.empty() || profiles_ - c.last_profile > kLookProfiles) continue;
    // Met at the heads' height, its top unseen: a vertical profile up its face.
    const bool top = c.horizontal && !c.top_m && c.vertical_views < p_.look_views &&
                     static_cast<int>(c.points.size()) >= p_.min_points;
    // Its top seen (a desk's, below the heads: a level profile passes over it, and a vertical one
    // gives one footprint cell at 2.7 m): a horizontal profile tilted down onto its face, the
    // same place each time so that its cells are confirmed.
    const bool below = c.top_m && c.vertical_views < 2 * p_.look_views;
    if (!top && !below) continue;
    Vec2 middle = Vec2::Zero();
    for (const Vec2& q : c.points) middle += q;
    middle /= static_cast<double>(c.points.size());
    const double d = (middle - from).norm();
    if (d >= nearest) continue;
    nearest = d;
    best = LookTarget{middle,
                      below ? std::optional<double>(*c.top_m - p_.look_below_top_m) : std::nullopt};
  }
  return best;
}

std::vector<spott_map::MapFeature> ObjectRecognizer::Take() {
  std::vector<spott_map::MapFeature> found;
  for (ObjectCandidate& c : candidates_) {
    if (!c.label.empty()) continue;
    Footprint fp;
    const bool out_of_view =
        profiles_ - c.last_profile >= static_cast<std::uint64_t>(p_.quiet_profiles);
    const ObjectModel* m = Classify(c, p_, &fp, out_of_view, db_);
    if (!m) continue;
    c.label = m->label;
    if (!fp.round && fp.short_m < m->depth_m) {
      // One face seen: the object goes on behind it, away from the heads.
      Vec2 normal(-std::sin(fp.yaw), std::cos(fp.yaw));
      if (normal.dot(fp.centre - c.viewer) < 0) normal = -normal;
      fp.centre += normal * (m->depth_m - fp.short_m) / 2;
      fp.short_m = m->depth_m;
    }
    spott_map::MapFeature f;
    f.type = m->type;
    f.label = m->label;
    f.pose = spott_map::Pose2{fp.centre.x(), fp.centre.y(), fp.yaw};
    f.size_x = fp.long_m;
    f.size_y = fp.short_m;
    f.size_z = c.top_m.value_or(c.height_seen_m);
    f.attributes["sensor"] = "quadris";
    std::ostringstream how;
    how << c.views << " profiles, " << c.Confirmed(p_).size() << " of " << c.points.size()
        << " cells confirmed" << (c.top_m ? ", top seen" : ", top not seen");
    f.attributes["recognized_from"] = how.str();
    found.push_back(std::move(f));
  }
  return found;
}

}  // namespace spott_tr_plus::controller
