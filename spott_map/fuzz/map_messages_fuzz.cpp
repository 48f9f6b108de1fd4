// Fuzzes the message conversions where the harmful inputs of issue 21 entered: a MapUpdate, a
// RoomDoorGraph and a MapFeatureArray built field by field from the fuzzer's bytes (any double,
// NaN, inf and 1e300 included; bounded counts), converted as the nodes convert them and applied
// to a map database as world_server does. Whatever is accepted must satisfy the size rule of
// spott_map/ros/conversions.h and convert back and forth unchanged in kind; nothing may crash.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "spott_map/map_database.h"
#include "spott_map/ros/conversions.h"
#include "spott_map/ros/map_update.h"
#include "spott_map/world_loader.h"

namespace {

namespace conv = spott_map::ros_conversions;

// Reads fields from the fuzzer's bytes; zeros once they run out.
class Bytes {
 public:
  Bytes(const uint8_t* d, size_t n) : d_(d), n_(n) {}
  uint8_t U8() { return i_ < n_ ? d_[i_++] : 0; }
  std::size_t Count(std::size_t max) { return U8() % (max + 1); }
  double Double() {  // a small number most of the time, any bit pattern otherwise
    const uint8_t how = U8();
    if (how < 160) return (static_cast<int>(U8()) - 128) / 8.0;
    uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = bits << 8 | U8();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  std::string Id(const char* const* known, std::size_t n_known) {
    const uint8_t k = U8();
    if (k < 200 && n_known > 0) return known[k % n_known];
    std::string s;
    for (std::size_t j = Count(6); j > 0; --j) s.push_back(static_cast<char>(U8()));
    return s;
  }
  geometry_msgs::Point Point() {
    geometry_msgs::Point p;
    p.x = Double();
    p.y = Double();
    p.z = U8() < 200 ? 0.0 : Double();
    return p;
  }

 private:
  const uint8_t* d_;
  size_t n_, i_ = 0;
};

const char* const kRooms[] = {"room_a", "room_b", "hall", "r1", "r2"};
const char* const kDoors[] = {"d_ab", "d_hall", "d1", "opening_1"};
const char* const kFeatures[] = {"wall_0", "wall_1", "sensed_1", "chair"};

spott_msgs::MapFeature Feature(Bytes& b) {
  spott_msgs::MapFeature f;
  f.id = b.Id(kFeatures, 4);
  f.type = b.U8() % 9;  // two values beyond GEON_ELLIPSOID
  f.source = b.U8() % 3;
  f.label = b.Id(kFeatures, 4);
  for (std::size_t k = b.Count(4); k > 0; --k) f.points.push_back(b.Point());
  f.pose.position = b.Point();
  f.pose.orientation.x = b.U8() < 220 ? 0.0 : b.Double();
  f.pose.orientation.y = b.U8() < 220 ? 0.0 : b.Double();
  f.pose.orientation.z = b.Double();
  f.pose.orientation.w = b.Double();
  f.size.x = b.Double();
  f.size.y = b.Double();
  f.size.z = b.Double();
  for (std::size_t k = b.Count(2); k > 0; --k) {
    spott_msgs::Attribute a;
    a.key = b.Id(kFeatures, 4);
    a.value = b.Id(kRooms, 5);
    f.attributes.push_back(a);
  }
  return f;
}

spott_msgs::RoomDoorGraph Graph(Bytes& b) {
  spott_msgs::RoomDoorGraph g;
  for (std::size_t k = b.Count(4); k > 0; --k) {
    spott_msgs::Room r;
    r.id = b.Id(kRooms, 5);
    r.kind = b.U8() % 3;
    for (std::size_t j = b.Count(6); j > 0; --j) {
      geometry_msgs::Point32 p;
      p.x = static_cast<float>(b.Double());
      p.y = static_cast<float>(b.Double());
      r.polygon.points.push_back(p);
    }
    g.rooms.push_back(r);
  }
  for (std::size_t k = b.Count(4); k > 0; --k) {
    spott_msgs::Door d;
    d.id = b.Id(kDoors, 4);
    d.room_a = b.Id(kRooms, 5);
    d.room_b = b.Id(kRooms, 5);
    d.kind = b.U8() % 3;
    d.state = b.U8() % 4;
    d.width = b.Double();
    d.centre = b.Point();
    for (std::size_t j = b.Count(3); j > 0; --j) d.opening.push_back(b.Point());
    g.doors.push_back(d);
  }
  return g;
}

// The size rule of conversions.h, which every accepted feature must keep.
void CheckAccepted(const spott_map::MapFeature& f) {
  const auto ok = [](double v, double max) { return std::isfinite(v) && std::abs(v) <= max; };
  for (const auto& p : f.points)
    if (!ok(p.x(), conv::kMaxCoordinateM) || !ok(p.y(), conv::kMaxCoordinateM)) std::abort();
  if (!ok(f.pose.x, conv::kMaxCoordinateM) || !ok(f.pose.y, conv::kMaxCoordinateM) ||
      !std::isfinite(f.pose.yaw))
    std::abort();
  for (double s : {f.size_x, f.size_y, f.size_z})
    if (!ok(s, conv::kMaxSizeM) || s < 0.0) std::abort();
}

const spott_map::MapDatabase& BaseDatabase() {
  static const spott_map::MapDatabase db = [] {
    const auto r = spott_map::LoadWorldFromString(R"(world:
  name: fuzz
rooms:
  - {id: room_a, polygon: [[0, 0], [4, 0], [4, 3], [0, 3]]}
  - {id: room_b, polygon: [[4, 0], [8, 0], [8, 3], [4, 3]]}
doors:
  - {id: d_ab, between: [room_a, room_b], center: [4, 1.5], width: 0.9, state: open}
robot_start:
  pose: [1, 1, 0]
)",
                                                  "fuzz.yaml");
    if (!r.ok()) std::abort();
    return spott_map::MapDatabase::FromWorld(*r.world);
  }();
  return db;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes b(data, size);
  // A feature array, as the planners convert it.
  for (std::size_t k = b.Count(6); k > 0; --k) {
    const spott_msgs::MapFeature m = Feature(b);
    std::string error;
    const auto f = conv::FromMsg(m, &error);
    if (!f) {
      if (error.empty()) std::abort();  // a refusal says why
      continue;
    }
    CheckAccepted(*f);
    const auto again = conv::FromMsg(conv::ToMsg(*f), &error);
    if (!again || again->type != f->type || again->points.size() != f->points.size()) std::abort();
  }
  // A graph, as the planners convert it.
  {
    std::string error;
    const auto g = conv::FromMsg(Graph(b), &error);
    if (!g && error.empty()) std::abort();
    if (g) {
      for (const auto& d : g->doors())
        if (!g->FindRoom(d.room_a) || !g->FindRoom(d.room_b)) std::abort();
      const auto again = conv::FromMsg(conv::ToMsg(*g, "fuzz", "map", ros::Time()), &error);
      if (!again || again->rooms().size() != g->rooms().size()) std::abort();
    }
  }
  // A map update, applied as world_server applies it.
  spott_msgs::MapUpdate u;
  for (std::size_t k = b.Count(4); k > 0; --k) u.added.push_back(Feature(b));
  for (std::size_t k = b.Count(2); k > 0; --k) u.relabelled.push_back(Feature(b));
  for (std::size_t k = b.Count(2); k > 0; --k) u.removed.push_back(b.Id(kFeatures, 4));
  for (std::size_t k = b.Count(3); k > 0; --k) {
    spott_msgs::DoorState d;
    d.door_id = b.Id(kDoors, 4);
    d.state = b.U8() % 4;
    u.doors.push_back(d);
  }
  spott_map::MapDatabase db = BaseDatabase();
  conv::ApplyMapUpdate(u, 0.1, db);
  for (const auto& f : db.features()) CheckAccepted(f);
  return 0;
}
