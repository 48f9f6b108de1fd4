// Fuzzes the map_server map reader (YAML + PGM) and the rasterization of the grid it gives:
// the input is the YAML text, then a line "---pgm---", then the image's bytes (the image the
// YAML names, whatever its name).
#include <cstddef>
#include <cstdint>
#include <string>

#include "markov_localization/map_model.h"
#include "markov_localization/occupancy_map.h"

namespace {
std::string image;
bool ReadImage(const std::string&, std::string* bytes) {
  *bytes = image;
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string sep = "\n---pgm---\n";
  const auto split = input.find(sep);
  const std::string yaml = input.substr(0, split);
  image =
      split == std::string::npos ? std::string("P2 1 1 255 0") : input.substr(split + sep.size());
  const auto r = markov_localization::ParseMapServerMap(yaml, "fuzz.yaml", &ReadImage);
  if (!r.ok() || r.map->width > 200 || r.map->height > 200) return 0;
  markov_localization::MapModelParameters p;
  p.resolution_m = 0.15;
  p.ray_cast_subdivision = 3;
  try {
    const auto map = markov_localization::MapModel::FromOccupancy(*r.map, p);
    volatile double d = map.RayCast(map.CellCentre(map.width() / 2, map.height() / 2), 0.3, 5.0);
    (void)d;
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
