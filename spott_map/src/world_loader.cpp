#include "spott_map/world_loader.h"

#include <sstream>

#include "spott_map/yaml_reader.h"
#include "spott_text/file_reading.h"
#include "world_validation.h"

namespace spott_map {

namespace {

std::string Describe(const char* section, std::size_t index, const std::string& id) {
  std::string s = std::string(section) + "[" + std::to_string(index) + "]";
  if (!id.empty()) s += " (" + id + ")";
  return s;
}

// Reads the id (or place name) under `key` and checks it against the one id rule (world.h),
// located at the id itself.
std::string ReadId(YamlReader& in, const YAML::Node& item, const char* key,
                   const std::string& what) {
  const std::string id = in.String(item, key, what, true).value_or("");
  if (item[key] && item[key].IsScalar() && !IsValidId(id)) {
    in.Error(item[key], what + ": '" + id + "' is not a valid " +
                            (std::string(key) == "name" ? "place name" : "id") + ": " + kIdRule);
  }
  return id;
}

// The id of a list item, read leniently so that later messages can name the item.
std::string PeekId(const YAML::Node& item, const char* key) {
  if (item.IsMap() && item[key] && item[key].IsScalar()) return item[key].Scalar();
  return "";
}

void ReadWorldHeader(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectMap(node, "world", {"name", "description"})) return;
  world.name = in.String(node, "name", "world", true).value_or("");
  world.description = in.String(node, "description", "world", false).value_or("");
}

void ReadRooms(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "rooms")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("rooms", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "name", "kind", "polygon"})) continue;
    Room room;
    room.where = in.Where(item);
    room.id = ReadId(in, item, "id", what);
    room.name = in.String(item, "name", what, false).value_or(room.id);
    if (auto kind = in.String(item, "kind", what, false)) {
      if (auto k = ParseRoomKind(*kind)) {
        room.kind = *k;
      } else {
        in.Error(item["kind"], what + ": kind must be room or hallway, got '" + *kind + "'");
      }
    }
    if (auto polygon = in.Points(item, "polygon", what, true, 3)) {
      room.polygon = *polygon;
    } else {
      continue;
    }
    world.rooms.push_back(room);
  }
}

void ReadDoors(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "doors")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("doors", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "between", "center", "width", "state", "kind"})) {
      continue;
    }
    Door door;
    door.where = in.Where(item);
    door.id = ReadId(in, item, "id", what);
    const YAML::Node between = item["between"];
    bool ok = true;
    if (!between) {
      ok = in.Require(item, "between", what);
    } else if (!between.IsSequence() || between.size() != 2 || !between[0].IsScalar() ||
               !between[1].IsScalar()) {
      in.Error(between, what + ": between: expected two room ids, e.g. [hall, office_1]");
      ok = false;
    } else {
      door.room_a = between[0].Scalar();
      door.room_b = between[1].Scalar();
    }
    auto center = in.Point(item, "center", what, true);
    auto width = in.Number(item, "width", what, true, NumberRule::kPositive);
    if (auto kind = in.String(item, "kind", what, false)) {
      if (auto k = ParseDoorKind(*kind)) {
        door.kind = *k;
      } else {
        in.Error(item["kind"], what + ": kind must be door or opening, got '" + *kind + "'");
      }
    }
    door.state = door.kind == DoorKind::kOpening ? DoorState::kOpen : DoorState::kUnknown;
    if (auto state = in.String(item, "state", what, false)) {
      if (auto s = ParseDoorState(*state)) {
        door.state = *s;
        if (door.kind == DoorKind::kOpening && *s != DoorState::kOpen) {
          in.Error(item["state"], what + ": an opening has no door leaf and is always open");
        }
      } else {
        in.Error(item["state"],
                 what + ": state must be open, closed or unknown, got '" + *state + "'");
      }
    }
    if (!ok || !center || !width) continue;
    door.center = *center;
    door.width = *width;
    world.doors.push_back(door);
  }
}

void ReadWalls(YamlReader& in, const YAML::Node& node, World& world, bool& from_rooms,
               double& thickness) {
  if (!in.ExpectMap(node, "walls", {"thickness", "from_rooms", "segments"})) return;
  thickness = in.Number(node, "thickness", "walls", false, NumberRule::kPositive).value_or(0.1);
  from_rooms = in.Bool(node, "from_rooms", "walls", false).value_or(false);
  const YAML::Node segments = node["segments"];
  if (!segments || !in.ExpectSequence(segments, "walls: segments")) return;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const YAML::Node item = segments[i];
    const std::string what = Describe("walls: segments", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "from", "to", "thickness"})) continue;
    Wall wall;
    wall.where = in.Where(item);
    wall.id = ReadId(in, item, "id", what);
    auto from = in.Point(item, "from", what, true);
    auto to = in.Point(item, "to", what, true);
    wall.thickness =
        in.Number(item, "thickness", what, false, NumberRule::kPositive).value_or(thickness);
    if (!from || !to) continue;
    wall.segment = Segment{*from, *to};
    world.walls.push_back(wall);
  }
}

void ReadObjects(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "objects")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("objects", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "kind", "pose", "size", "height", "label"})) continue;
    WorldObject object;
    object.where = in.Where(item);
    object.id = ReadId(in, item, "id", what);
    object.label = in.String(item, "label", what, false).value_or("");
    bool ok = true;
    if (auto kind = in.String(item, "kind", what, true)) {
      if (auto k = ParseObjectKind(*kind)) {
        object.kind = *k;
      } else {
        in.Error(item["kind"], what +
                                   ": kind must be one of chair, desk, partition, shelf, "
                                   "cuboid, cylinder; got '" +
                                   *kind + "'");
        ok = false;
      }
    }
    auto pose = in.Pose(item, "pose", what, true);
    auto size = in.Numbers(item, "size", what, true, 2, NumberRule::kPositive);
    auto height = in.Number(item, "height", what, true, NumberRule::kPositive);
    if (!ok || !pose || !size || !height) continue;
    object.pose = *pose;
    object.size_x = (*size)[0];
    object.size_y = (*size)[1];
    object.height = *height;
    world.objects.push_back(object);
  }
}

void ReadPlaces(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "places")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("places", i, PeekId(item, "name"));
    if (!in.ExpectMap(item, what, {"name", "kind", "pose"})) continue;
    Place place;
    place.where = in.Where(item);
    place.name = ReadId(in, item, "name", what);
    place.kind = in.String(item, "kind", what, false).value_or("waypoint");
    if (place.kind != "localization" && place.kind != "position" && place.kind != "landmark" &&
        place.kind != "waypoint") {
      in.Error(item["kind"], what +
                                 ": kind must be localization, position, landmark or "
                                 "waypoint; got '" +
                                 place.kind + "'");
    }
    auto pose = in.Pose(item, "pose", what, true);
    if (!pose) continue;
    place.pose = *pose;
    world.places.push_back(place);
  }
}

void ReadZones(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "zones")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("zones", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "polygon"})) continue;
    Zone zone;
    zone.where = in.Where(item);
    zone.id = ReadId(in, item, "id", what);
    auto polygon = in.Points(item, "polygon", what, true, 3);
    if (!polygon) continue;
    zone.polygon = *polygon;
    world.zones.push_back(zone);
  }
}

void ReadPaths(YamlReader& in, const YAML::Node& node, World& world) {
  if (!in.ExpectSequence(node, "paths")) return;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string what = Describe("paths", i, PeekId(item, "id"));
    if (!in.ExpectMap(item, what, {"id", "points", "final_yaw"})) continue;
    NamedPath path;
    path.where = in.Where(item);
    path.id = ReadId(in, item, "id", what);
    path.final_yaw = in.Number(item, "final_yaw", what, false);
    auto points = in.Points(item, "points", what, true, 1);
    if (!points) continue;
    path.points = *points;
    world.paths.push_back(path);
  }
}

}  // namespace

WorldLoadResult LoadWorldFromString(const std::string& text, const std::string& source_name) {
  YamlReader in(source_name);
  WorldLoadResult result;
  World world;
  world.source_file = source_name;
  bool walls_from_rooms = false;
  double wall_thickness = 0.1;
  SourceLocation start_where;

  const YAML::Node root = in.Parse(text);
  if (in.errors().empty()) {
    if (in.ExpectMap(root, "world file",
                     {"world", "walls", "rooms", "doors", "objects", "places", "zones", "paths",
                      "robot_start"})) {
      if (in.Require(root, "world", "world file")) ReadWorldHeader(in, root["world"], world);
      if (in.Require(root, "rooms", "world file")) ReadRooms(in, root["rooms"], world);
      if (root["walls"]) ReadWalls(in, root["walls"], world, walls_from_rooms, wall_thickness);
      if (root["doors"]) ReadDoors(in, root["doors"], world);
      if (root["objects"]) ReadObjects(in, root["objects"], world);
      if (root["places"]) ReadPlaces(in, root["places"], world);
      if (root["zones"]) ReadZones(in, root["zones"], world);
      if (root["paths"]) ReadPaths(in, root["paths"], world);
      if (in.Require(root, "robot_start", "world file")) {
        const YAML::Node start = root["robot_start"];
        start_where = in.Where(start);
        if (in.ExpectMap(start, "robot_start", {"pose"})) {
          if (auto pose = in.Pose(start, "pose", "robot_start", true)) world.robot_start = *pose;
        }
      }
    }
  }
  result.errors = in.errors();
  result.warnings = in.warnings();
  // Geometry is checked only on a structurally sound file, so each error has one cause.
  if (result.errors.empty()) {
    ValidateWorld(world, start_where, walls_from_rooms, wall_thickness, result.errors,
                  result.warnings);
  }
  if (result.errors.empty()) result.world = std::move(world);
  return result;
}

WorldLoadResult LoadWorldFile(const std::string& path) {
  std::string error;
  const auto text = spott_text::ReadTextFile(path, &error);
  if (!text) {
    WorldLoadResult result;
    result.errors.push_back(SourceError{SourceLocation{path, 0, 0}, "cannot read world file: " + error});
    return result;
  }
  return LoadWorldFromString(*text, path);
}

}  // namespace spott_map
