// The TR+ controller's sensor messages (src/ros/sensor_conversions.h) built field by field from
// the fuzzer's bytes (any sizes, NaN, infinities, huge and negative numbers), taken as the node
// takes them: a sonar or infrared ring through RingFromMsg, a bumper ring through PressedAngles,
// a QUADRIS profile with any head pose through ProfilePoints, places through PlacesProblem and
// PlacesFromMsg; what is accepted then goes into an evidence grid (a SensorMapper laid out as
// without an a priori map) as the controller's core takes it. Accepted input must be usable:
// readings dropped out (NaN) or in [0, max_range], finite bumper angles, finite profile points,
// finite places, fused features with finite points; a refusal names its field ("field: why").
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_messages.h"
#include "fuzz_values.h"
#include "spott_map/map_database.h"
#include "spott_map/ros/conversions.h"
#include "spott_tr_plus/ros/sensor_conversions.h"

namespace conv = spott_tr_plus::ros_conversions;
namespace ctl = spott_tr_plus::controller;

namespace {

using spott_fuzz::AnyNumber;
void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "controller_messages_fuzz", what); }
void CheckRefusal(const std::string& problem) {
  Check(spott_fuzz::NamesField(problem), "a refusal without 'field: why'");
}

ctl::Pose2 RobotPose(FuzzedDataProvider& in) {
  // The node's poses come from tf through spott_ros::LookupRobotPose: finite.
  return ctl::Pose2{in.ConsumeFloatingPointInRange<double>(-5.0, 5.0),
                    in.ConsumeFloatingPointInRange<double>(-5.0, 5.0),
                    in.ConsumeFloatingPointInRange<double>(-4.0, 4.0)};
}

// The grid as the controller lays it out with no a priori map, and what it fuses.
void CheckFused(ctl::SensorMapper& mapper, const spott_map::MapDatabase& db) {
  const ctl::SensedBatch batch = mapper.Take(db);
  for (const spott_map::MapFeature& f : batch.features) {
    Check(std::isfinite(f.pose.x) && std::isfinite(f.pose.y), "a fused feature not finite");
    for (const auto& p : f.points) Check(p.allFinite(), "a fused feature's point not finite");
  }
}

void Ring(FuzzedDataProvider& in) {
  const spott_msgs::RangeRing msg = spott_fuzz::AnyRangeRing(in);
  std::string problem;
  int discarded = -2;
  const auto ring = conv::RingFromMsg(msg, &problem, &discarded);
  if (!ring) return CheckRefusal(problem);
  Check(discarded >= -1 && discarded < static_cast<int>(msg.ranges.size()), "a discarded index");
  Check(ring->mounts.size() == ring->ranges.size(), "not one mount per reading");
  for (double r : ring->ranges)
    Check(std::isnan(r) || (r >= 0.0 && r <= ring->max_range_m * 1.001),
          "a reading neither dropped out nor in [0, max_range]");
  const spott_map::MapDatabase db;
  ctl::SensorMapper mapper("sonar", ctl::MappingParameters{}, ctl::DoorSensingParameters{}, true);
  const ctl::Pose2 robot = RobotPose(in);
  mapper.SetMap(db, robot.Position());
  const int times = in.ConsumeIntegralInRange<int>(1, 8);
  for (int k = 0; k < times; ++k) mapper.AddRing(*ring, robot);
  CheckFused(mapper, db);
}

void Bumper(FuzzedDataProvider& in) {
  spott_msgs::BumperRing msg;
  const int n = in.ConsumeIntegralInRange<int>(0, 24);
  for (int i = 0; i < n; ++i) msg.pressed.push_back(in.ConsumeBool());
  const int angles = in.ConsumeIntegralInRange<int>(0, 24);
  for (int i = 0; i < angles; ++i) msg.segment_angles.push_back(AnyNumber<float>(in, -7.0f, 7.0f));
  for (double a : conv::PressedAngles(msg)) Check(std::isfinite(a), "a pressed angle not finite");
}

void Profile(FuzzedDataProvider& in) {
  spott_msgs::RangeProfile msg;
  msg.max_range = AnyNumber<float>(in, -1.0f, 5.0f);
  const int n = in.ConsumeIntegralInRange<int>(0, 40);
  for (int i = 0; i < n; ++i) {
    geometry_msgs::Point32 p;
    p.x = AnyNumber<float>(in, -5.0f, 5.0f);
    p.y = AnyNumber<float>(in, -5.0f, 5.0f);
    p.z = AnyNumber<float>(in, -2.0f, 2.0f);
    msg.points.push_back(p);
  }
  const int ranges = in.ConsumeBool() ? n : in.ConsumeIntegralInRange<int>(0, 41);
  for (int i = 0; i < ranges; ++i) msg.ranges.push_back(AnyNumber<float>(in, -1.0f, 6.0f));
  geometry_msgs::Transform head;
  head.translation.x = AnyNumber<double>(in, -1.0, 1.0);
  head.translation.y = AnyNumber<double>(in, -1.0, 1.0);
  head.translation.z = AnyNumber<double>(in, -1.0, 2.0);
  head.rotation.x = AnyNumber<double>(in, -1.0, 1.0);
  head.rotation.y = AnyNumber<double>(in, -1.0, 1.0);
  head.rotation.z = AnyNumber<double>(in, -1.0, 1.0);
  head.rotation.w = AnyNumber<double>(in, -1.0, 1.0);
  ctl::Vec2 origin;
  const auto points = conv::ProfilePoints(msg, head, 0.05, 1.8, &origin);
  if (!points) return;
  Check(origin.allFinite(), "an accepted head pose whose origin is not finite");
  for (const ctl::Vec2& p : *points) Check(p.allFinite(), "a profile point not finite");
  const spott_map::MapDatabase db;
  ctl::SensorMapper mapper("quadris", ctl::MappingParameters{}, ctl::DoorSensingParameters{}, true);
  const ctl::Pose2 robot = RobotPose(in);
  mapper.SetMap(db, robot.Position());
  for (int k = 0; k < 3; ++k) mapper.AddPoints(origin, *points, robot);
  CheckFused(mapper, db);
  // The same message for recognition: every sample, both orientations, named or not.
  ctl::Vec3 head_origin;
  const auto samples = conv::ProfileSamples(msg, head, &head_origin);
  Check(samples.has_value(), "a head pose accepted for mapping refused for recognition");
  Check(samples->size() == msg.points.size(), "a profile sample lost");
  ctl::ObjectRecognizer recognizer{ctl::RecognitionParameters{}};
  recognizer.SetMap(&db);
  for (int k = 0; k < 12; ++k) recognizer.AddProfile(head_origin, *samples, k % 2 == 1);
  if (const auto look = recognizer.ToLookAt(robot.Position()))
    Check(look->at.allFinite() && (!look->height || std::isfinite(*look->height)),
          "a head sent to look at a place that is not finite");
  for (const spott_map::MapFeature& f : recognizer.Take()) {
    Check(!f.label.empty() && std::isfinite(f.pose.x) && std::isfinite(f.pose.y) &&
              std::isfinite(f.size_x) && std::isfinite(f.size_z),
          "a recognised object without a label or a finite place");
  }
}

void Places(FuzzedDataProvider& in) {
  spott_msgs::WorldPlaces msg;
  const int n = in.ConsumeIntegralInRange<int>(0, 4);
  for (int i = 0; i < n; ++i) {
    spott_msgs::NamedPlace p;
    p.name = in.ConsumeRandomLengthString(12);
    p.kind = in.ConsumeRandomLengthString(8);
    p.pose.x = AnyNumber<double>(in, -5.0, 5.0);
    p.pose.y = AnyNumber<double>(in, -5.0, 5.0);
    p.pose.theta = AnyNumber<double>(in, -4.0, 4.0);
    msg.places.push_back(p);
  }
  const std::string problem = spott_map::ros_conversions::PlacesProblem(msg);
  if (!problem.empty()) return CheckRefusal(problem);
  const auto places = conv::PlacesFromMsg(msg);
  Check(places.size() == msg.places.size(), "places lost in the conversion");
  for (const auto& p : places)
    Check(std::isfinite(p.pose.x) && std::isfinite(p.pose.y) && std::isfinite(p.pose.yaw),
          "an accepted place that is not finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0:
      Ring(in);
      break;
    case 1:
      Bumper(in);
      break;
    case 2:
      Profile(in);
      break;
    default:
      Places(in);
      break;
  }
  return 0;
}
