// Fuzzes the task-command parser and interpreter. Properties: diagnostics are located on line 1
// inside the text, a parsed command prints to text that parses back to the same text, and
// interpretation never yields a non-finite goal. Each command is interpreted twice: without a
// map, and against a small map (two rooms, a door, a desk; names resolved in it), where a goal
// must lie in one of the rooms it is restricted to.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"
#include "spott_tr_plus/task_command.h"

namespace {

const char* kWorld = R"(world: {name: fuzz}
walls: {from_rooms: true, thickness: 0.1}
rooms:
  - {id: hall, kind: hallway, polygon: [[0, 0], [8, 0], [8, 2], [0, 2]]}
  - {id: office, polygon: [[0, 2], [4, 2], [4, 5], [0, 5]]}
doors:
  - {id: d1, between: [hall, office], center: [2, 2], width: 0.9}
places:
  - {name: p1, pose: [6, 1, 0]}
robot_start: {pose: [1, 1, 0]}
)";

struct Map {
  spott_map::World world;
  spott_map::MapDatabase db;
  spott_tr_plus::PlaceResolver resolve;
  spott_tr_plus::TaskMap map;
  Map() {
    world = *spott_map::LoadWorldFromString(kWorld, "fuzz.yaml").world;
    db = spott_map::MapDatabase::FromWorld(world);
    spott_map::MapFeature desk;
    desk.id = "desk1";
    desk.type = spott_map::FeatureType::kRectangle;
    desk.pose = {2, 4.4, 0};
    desk.size_x = 1.2;
    desk.size_y = 0.6;
    db.AddFeature(desk);
    resolve = spott_tr_plus::MapPlaceResolver(db, world.places);
    map.database = &db;
    map.padding_m = 0.325;
  }
};

void CheckGoal(const spott_tr_plus::TaskInterpretResult& in, const spott_map::MapDatabase* db) {
  if (!in.ok()) return;
  const auto& i = *in.interpretation;
  if (i.goal && !(std::isfinite(i.goal->goal_x) && std::isfinite(i.goal->goal_y))) std::abort();
  if (db && i.goal) {
    bool listed = false;
    for (const auto& id : i.goal->rooms) {
      const spott_map::Room* room = db->graph().FindRoom(id);
      listed = listed ||
               (room && spott_map::PointInPolygon({i.goal->goal_x, i.goal->goal_y}, room->polygon));
    }
    if (!listed) std::abort();
  }
  const auto b = i.bias.At(0.0, 0.0, 0.0);
  (void)b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 1024) return 0;
  static const Map map;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const spott_tr_plus::TaskParseResult r = spott_tr_plus::ParseTaskCommand(text);
  for (const auto& d : r.diagnostics) {
    if (d.where.line < 1 || d.where.column < 1) std::abort();
  }
  if (!r.ok()) return 0;
  const std::string printed = spott_tr_plus::ToText(*r.command);
  const spott_tr_plus::TaskParseResult again = spott_tr_plus::ParseTaskCommand(printed);
  if (!again.ok() || spott_tr_plus::ToText(*again.command) != printed) std::abort();
  const spott_tr_plus::TaskInterpretationParameters params;
  CheckGoal(spott_tr_plus::InterpretTask(*r.command, 1.0, 2.0, 0.5, params), nullptr);
  spott_tr_plus::TaskInterpretationParameters coarse;
  coarse.free_space_resolution_m = 0.1;  // keeps each run short
  CheckGoal(spott_tr_plus::InterpretTask(*r.command, 1.0, 1.0, 0.5, coarse, map.map, map.resolve),
            &map.db);
  return 0;
}
