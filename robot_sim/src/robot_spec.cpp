#include "robot_sim/robot_spec.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <urdf_parser/urdf_parser.h>
#include <Eigen/Geometry>

#include "spott_map/yaml_reader.h"

namespace robot_sim {

using spott_map::NumberRule;
using spott_map::SourceError;
using spott_map::SourceLocation;
using spott_map::YamlReader;

const RangeRingSpec* RobotSpec::FindRing(const std::string& ring_name) const {
  for (const RangeRingSpec& ring : rings) {
    if (ring.name == ring_name) return &ring;
  }
  return nullptr;
}

namespace {

// A count (rays, beams, segments ...): a whole number in [lo, hi], else an error naming the key
// and `fallback`. Checked before the conversion: a huge number made int overflow
// (robot_file_fuzz: `rays: 8.9e61`).
int Count(YamlReader& in, const YAML::Node& node, const char* key, const std::string& what,
          bool required, int lo, int hi, int fallback) {
  const auto v = in.Number(node, key, what, required);
  if (!v) return fallback;
  if (!(*v >= lo && *v <= hi) || *v != std::floor(*v)) {
    in.Error(node[key], what + ": " + key + " must be a whole number in [" + std::to_string(lo) +
                            ", " + std::to_string(hi) + "]");
    return fallback;
  }
  return static_cast<int>(*v);
}

// Pose of `link` in `root`, following the joint chain with every movable joint at zero.
std::optional<Eigen::Isometry3d> LinkPoseIn(const urdf::ModelInterface& model,
                                            const std::string& link, const std::string& root) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  urdf::LinkConstSharedPtr current = model.getLink(link);
  for (int depth = 0; current && depth < 64; ++depth) {
    if (current->name == root) return pose;
    const urdf::JointConstSharedPtr joint = current->parent_joint;
    if (!joint) return std::nullopt;
    const urdf::Pose& o = joint->parent_to_joint_origin_transform;
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.translate(Eigen::Vector3d(o.position.x, o.position.y, o.position.z));
    step.rotate(Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z));
    pose = step * pose;
    current = model.getLink(joint->parent_link_name);
  }
  return std::nullopt;
}

std::optional<Mount> MountOf(const urdf::ModelInterface& model, const std::string& link,
                             const std::string& root) {
  const auto pose = LinkPoseIn(model, link, root);
  if (!pose) return std::nullopt;
  Mount m;
  m.frame_id = link;
  m.x = pose->translation().x();
  m.y = pose->translation().y();
  m.z = pose->translation().z();
  const Eigen::Vector3d axis = pose->linear() * Eigen::Vector3d::UnitX();
  m.yaw = std::atan2(axis.y(), axis.x());
  return m;
}

SourceError UrdfError(const std::string& urdf_name, const std::string& message) {
  return SourceError{SourceLocation{urdf_name, 0, 0}, message};
}

void ReadDrive(YamlReader& in, const YAML::Node& node, DriveSpec& drive) {
  if (!in.ExpectMap(node, "drive",
                    {"kind", "max_linear_mps", "max_angular_rps", "max_linear_accel",
                     "max_angular_accel", "wheel_separation_m", "max_turret_rps"})) {
    return;
  }
  const std::string kind = in.String(node, "kind", "drive", true).value_or("synchro");
  if (kind == "synchro") {
    drive.kind = DriveKind::kSynchro;
  } else if (kind == "differential") {
    drive.kind = DriveKind::kDifferential;
  } else {
    in.Error(node["kind"], "drive: kind must be synchro or differential, got '" + kind + "'");
  }
  const auto positive = NumberRule::kPositive;
  drive.max_linear_mps = in.Number(node, "max_linear_mps", "drive", true, positive).value_or(0.5);
  drive.max_angular_rps = in.Number(node, "max_angular_rps", "drive", true, positive).value_or(1);
  drive.max_linear_accel =
      in.Number(node, "max_linear_accel", "drive", true, positive).value_or(0.5);
  drive.max_angular_accel =
      in.Number(node, "max_angular_accel", "drive", true, positive).value_or(2);
  drive.wheel_separation_m = in.Number(node, "wheel_separation_m", "drive",
                                       drive.kind == DriveKind::kDifferential, positive)
                                 .value_or(0.0);
  drive.max_turret_rps =
      in.Number(node, "max_turret_rps", "drive", false, NumberRule::kNonNegative).value_or(0.0);
}

void ReadRing(YamlReader& in, const YAML::Node& node, const std::string& what,
              RangeRingSpec& ring) {
  if (!in.ExpectMap(
          node, what,
          {"name", "kind", "link_prefix", "field_of_view", "min_range", "max_range", "rays",
           "vertical_rays", "critical_angle", "noise_stddev", "noise_per_metre", "fire_groups"})) {
    return;
  }
  ring.name = in.String(node, "name", what, true).value_or("");
  const std::string kind = in.String(node, "kind", what, true).value_or("ultrasound");
  if (kind == "ultrasound") {
    ring.kind = RangeKind::kUltrasound;
  } else if (kind == "infrared") {
    ring.kind = RangeKind::kInfrared;
  } else {
    in.Error(node["kind"], what + ": kind must be ultrasound or infrared, got '" + kind + "'");
  }
  ring.link_prefix = in.String(node, "link_prefix", what, true).value_or("");
  const auto pos = NumberRule::kPositive;
  const auto nonneg = NumberRule::kNonNegative;
  ring.field_of_view = in.Number(node, "field_of_view", what, true, pos).value_or(0.5);
  ring.min_range = in.Number(node, "min_range", what, true, nonneg).value_or(0.0);
  ring.max_range = in.Number(node, "max_range", what, true, pos).value_or(1.0);
  ring.rays = Count(in, node, "rays", what, true, 1, 1000, 1);
  ring.vertical_rays = Count(in, node, "vertical_rays", what, false, 1, 100, 1);
  ring.critical_angle = in.Number(node, "critical_angle", what, true, pos).value_or(1.5708);
  ring.noise_stddev = in.Number(node, "noise_stddev", what, true, nonneg).value_or(0.0);
  ring.noise_per_metre = in.Number(node, "noise_per_metre", what, false, nonneg).value_or(0.0);
  ring.fire_groups = Count(in, node, "fire_groups", what, false, 1, 1000, 0);
  if (ring.field_of_view >= M_PI) in.Error(node["field_of_view"], what + ": field_of_view >= pi");
  if (ring.max_range <= ring.min_range) {
    in.Error(node["max_range"], what + ": max_range must exceed min_range");
  }
  if (ring.critical_angle > M_PI / 2 + 1e-3) {
    in.Error(node["critical_angle"], what + ": critical_angle must be at most pi/2");
  }
}

void ReadLaser(YamlReader& in, const YAML::Node& node, LaserSpec& laser) {
  if (!in.ExpectMap(node, "laser",
                    {"name", "link", "angle_min", "angle_max", "beams", "min_range", "max_range",
                     "noise_stddev"})) {
    return;
  }
  laser.name = in.String(node, "name", "laser", false).value_or("laser");
  laser.link = in.String(node, "link", "laser", true).value_or("");
  laser.angle_min = in.Number(node, "angle_min", "laser", true).value_or(-1.5708);
  laser.angle_max = in.Number(node, "angle_max", "laser", true).value_or(1.5708);
  laser.beams = Count(in, node, "beams", "laser", true, 2, 100000, 2);
  laser.min_range =
      in.Number(node, "min_range", "laser", true, NumberRule::kNonNegative).value_or(0.0);
  laser.max_range =
      in.Number(node, "max_range", "laser", true, NumberRule::kPositive).value_or(1.0);
  laser.noise_stddev =
      in.Number(node, "noise_stddev", "laser", true, NumberRule::kNonNegative).value_or(0.0);
  if (laser.angle_max <= laser.angle_min) {
    in.Error(node["angle_max"], "laser: angle_max must exceed angle_min");
  }
  if (laser.max_range <= laser.min_range) {
    in.Error(node["max_range"], "laser: max_range must exceed min_range");
  }
}

void ReadProfiler(YamlReader& in, const YAML::Node& node, const std::string& what,
                  ProfilerSpec& p) {
  if (!in.ExpectMap(node, what,
                    {"name", "link", "pan_joint", "tilt_joint", "samples", "field_of_view",
                     "min_range", "max_range", "noise_stddev"})) {
    return;
  }
  p.name = in.String(node, "name", what, true).value_or("");
  p.link = in.String(node, "link", what, true).value_or("");
  p.pan_joint = in.String(node, "pan_joint", what, true).value_or("");
  p.tilt_joint = in.String(node, "tilt_joint", what, true).value_or("");
  p.samples = Count(in, node, "samples", what, true, 2, 10000, 2);
  p.field_of_view =
      in.Number(node, "field_of_view", what, true, NumberRule::kPositive).value_or(0.7);
  p.min_range = in.Number(node, "min_range", what, true, NumberRule::kNonNegative).value_or(0.0);
  p.max_range = in.Number(node, "max_range", what, true, NumberRule::kPositive).value_or(1.0);
  p.noise_stddev =
      in.Number(node, "noise_stddev", what, true, NumberRule::kNonNegative).value_or(0.0);
  if (p.field_of_view >= M_PI) in.Error(node["field_of_view"], what + ": field_of_view >= pi");
  if (p.max_range <= p.min_range) {
    in.Error(node["max_range"], what + ": max_range must exceed min_range");
  }
}

void ReadBumper(YamlReader& in, const YAML::Node& node, BumperSpec& bumper) {
  if (!in.ExpectMap(node, "bumper", {"segments", "travel_m"})) return;
  bumper.segments = Count(in, node, "segments", "bumper", true, 1, 360, 1);
  bumper.travel_m =
      in.Number(node, "travel_m", "bumper", true, NumberRule::kPositive).value_or(0.01);
}

// Body and mounts from the URDF.
void ReadUrdf(const std::string& urdf_xml, const std::string& urdf_name, RobotSpec& spec,
              std::vector<SourceError>& errors) {
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(urdf_xml);
  } catch (const std::exception& e) {
    errors.push_back(UrdfError(urdf_name, std::string("cannot parse URDF: ") + e.what()));
    return;
  }
  if (!model) {
    errors.push_back(UrdfError(urdf_name, "cannot parse URDF (not a valid <robot> document)"));
    return;
  }
  const urdf::LinkConstSharedPtr base = model->getLink(spec.base_frame);
  if (!base) {
    errors.push_back(UrdfError(urdf_name, "no link named '" + spec.base_frame + "'"));
    return;
  }
  const urdf::Cylinder* body = nullptr;
  if (base->collision && base->collision->geometry &&
      base->collision->geometry->type == urdf::Geometry::CYLINDER) {
    body = static_cast<const urdf::Cylinder*>(base->collision->geometry.get());
  }
  if (!body || !(body->radius > 0) || !(body->length > 0)) {
    errors.push_back(UrdfError(
        urdf_name, "link '" + spec.base_frame + "' needs a <collision> cylinder (the body)"));
    return;
  }
  for (const auto& [name, joint] : model->joints_) {
    if (joint->type == urdf::Joint::FIXED) continue;
    spec.movable_joints.push_back(name);
    if (name == "turret_joint") spec.turret_joint = name;
  }
  spec.radius_m = body->radius;
  spec.height_m = body->length;
  for (RangeRingSpec& ring : spec.rings) {
    ring.mounts.clear();
    for (int n = 1;; ++n) {
      const std::string link = ring.link_prefix + std::to_string(n);
      if (!model->getLink(link)) break;
      auto mount = MountOf(*model, link, spec.base_frame);
      if (!mount) {
        errors.push_back(
            UrdfError(urdf_name, "link '" + link + "' is not below '" + spec.base_frame + "'"));
        break;
      }
      ring.mounts.push_back(*mount);
    }
    if (ring.mounts.empty()) {
      errors.push_back(
          UrdfError(urdf_name, "ring '" + ring.name + "': no link '" + ring.link_prefix + "1'"));
    }
    if (ring.fire_groups <= 0 || ring.fire_groups > static_cast<int>(ring.mounts.size())) {
      ring.fire_groups = static_cast<int>(ring.mounts.size());
    }
  }
  for (ProfilerSpec& p : spec.profilers) {
    auto mount = MountOf(*model, p.link, spec.base_frame);
    if (!mount) {
      errors.push_back(UrdfError(
          urdf_name,
          "profiler link '" + p.link + "' missing or not below '" + spec.base_frame + "'"));
      continue;
    }
    p.mount = *mount;
    for (const std::string& j : {p.pan_joint, p.tilt_joint}) {
      if (!model->getJoint(j)) {
        errors.push_back(UrdfError(urdf_name, "profiler '" + p.name + "': no joint '" + j + "'"));
      }
    }
  }
  if (spec.laser) {
    auto mount = MountOf(*model, spec.laser->link, spec.base_frame);
    if (!mount) {
      errors.push_back(UrdfError(
          urdf_name,
          "laser link '" + spec.laser->link + "' missing or not below '" + spec.base_frame + "'"));
    } else {
      spec.laser->mount = *mount;
    }
  }
}

}  // namespace

RobotSpecResult LoadRobotSpecFromStrings(const std::string& robot_yaml,
                                         const std::string& yaml_name, const std::string& urdf_xml,
                                         const std::string& urdf_name) {
  RobotSpecResult result;
  YamlReader in(yaml_name);
  const YAML::Node root = in.Parse(robot_yaml);
  RobotSpec spec;
  if (root && in.ExpectMap(root, "robot file",
                           {"name", "drive", "rings", "laser", "bumper", "range_profilers"})) {
    spec.name = in.String(root, "name", "robot file", true).value_or("");
    if (in.Require(root, "drive", "robot file")) ReadDrive(in, root["drive"], spec.drive);
    if (root["rings"] && in.ExpectSequence(root["rings"], "rings")) {
      for (std::size_t i = 0; i < root["rings"].size(); ++i) {
        RangeRingSpec ring;
        const std::string what = "rings[" + std::to_string(i) + "]";
        ReadRing(in, root["rings"][i], what, ring);
        if (spec.FindRing(ring.name)) {
          in.Error(root["rings"][i], what + ": duplicate ring name '" + ring.name + "'");
        }
        spec.rings.push_back(ring);
      }
    }
    if (root["range_profilers"] && in.ExpectSequence(root["range_profilers"], "range_profilers")) {
      for (std::size_t i = 0; i < root["range_profilers"].size(); ++i) {
        ProfilerSpec p;
        ReadProfiler(in, root["range_profilers"][i], "range_profilers[" + std::to_string(i) + "]",
                     p);
        spec.profilers.push_back(p);
      }
    }
    if (root["laser"]) {
      spec.laser.emplace();
      ReadLaser(in, root["laser"], *spec.laser);
    }
    if (root["bumper"]) {
      spec.bumper.emplace();
      ReadBumper(in, root["bumper"], *spec.bumper);
    }
  }
  result.errors = in.errors();
  if (!result.errors.empty()) return result;
  ReadUrdf(urdf_xml, urdf_name, spec, result.errors);
  if (result.errors.empty()) result.spec = std::move(spec);
  return result;
}

RobotSpecResult LoadRobotSpec(const std::string& robot_yaml_path, const std::string& urdf_path) {
  auto read = [](const std::string& path, std::string& text) {
    std::ifstream file(path);
    if (!file) return false;
    std::ostringstream s;
    s << file.rdbuf();
    text = s.str();
    return true;
  };
  std::string yaml, urdf;
  RobotSpecResult result;
  if (!read(robot_yaml_path, yaml)) {
    result.errors.push_back({SourceLocation{robot_yaml_path, 0, 0}, "cannot open robot file"});
  }
  if (!read(urdf_path, urdf)) {
    result.errors.push_back({SourceLocation{urdf_path, 0, 0}, "cannot open URDF file"});
  }
  if (!result.errors.empty()) return result;
  return LoadRobotSpecFromStrings(yaml, robot_yaml_path, urdf, urdf_path);
}

}  // namespace robot_sim
