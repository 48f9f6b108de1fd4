// Fuzzes the world-file loader: any text must give either a world or located errors, never a
// crash, a hang or an error without a position. A world that loads is also turned into the map
// database and the local window, as world_server does with it.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spott_map/local_map.h"
#include "spott_map/map_database.h"
#include "spott_map/room_door_graph.h"
#include "spott_map/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const spott_map::WorldLoadResult result = spott_map::LoadWorldFromString(text, "fuzz.yaml");
  if (!result.ok()) {
    if (result.errors.empty()) std::abort();  // a refused world must say why
    for (const spott_map::SourceError& e : result.errors) {
      if (e.where.file != "fuzz.yaml" || e.message.empty()) std::abort();
    }
    return 0;
  }
  const spott_map::World& world = *result.world;
  const spott_map::RoomDoorGraph graph(world);
  graph.RoomContaining(world.robot_start.Position());
  spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(world);
  spott_map::LocalMap local(spott_map::LocalMapParameters{});
  local.Recentre(db, world.robot_start.Position());
  return 0;
}
