// spott_map_render WORLD.yaml OUT.png [--pixels-per-metre N] [--no-labels]
#include <cstdlib>
#include <iostream>
#include <string>

#include "spott_map/world_loader.h"
#include "spott_map/world_renderer.h"

int main(int argc, char** argv) {
  const std::string usage =
      "usage: spott_map_render WORLD.yaml OUT.png [--pixels-per-metre N] [--no-labels]";
  if (argc < 3) {
    std::cerr << usage << "\n";
    return 2;
  }
  spott_map::RenderOptions options;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--pixels-per-metre" && i + 1 < argc) {
      char* end = nullptr;
      options.pixels_per_metre = std::strtod(argv[++i], &end);
      if (*end != '\0') {
        std::cerr << "--pixels-per-metre: not a number: " << argv[i] << "\n";
        return 2;
      }
    } else if (arg == "--no-labels") {
      options.labels = false;
    } else {
      std::cerr << "unknown option " << arg << "\n" << usage << "\n";
      return 2;
    }
  }
  const spott_map::WorldLoadResult loaded = spott_map::LoadWorldFile(argv[1]);
  for (const auto& w : loaded.warnings) std::cerr << "warning: " << w.ToString() << "\n";
  if (!loaded.ok()) {
    std::cerr << spott_map::FormatErrors(loaded.errors) << "\n";
    return 1;
  }
  if (auto error = spott_map::RenderWorldToPng(*loaded.world, argv[2], options)) {
    std::cerr << *error << "\n";
    return 1;
  }
  std::cout << "wrote " << argv[2] << "\n";
  return 0;
}
