// Object recognition's cost per QUADRIS profile (object_recognition.h), on cim_office's CAD map
// (the map database the controller holds): the Nomad in office 101 looking around, its heads
// sweeping across the desk and chair that the map lacks and a drum put beside them; each step a
// horizontal and a vertical profile of 64 samples cast as robot_sim would (test/
// profile_caster.h), then Take() as the QUADRIS condition calls it at 2 Hz.
//  - BM_RecognitionProfile: AddProfile of one profile (the node calls it for every profile: two
//    heads, both orientations, about 1 Hz each), with Take every fourth profile.
// Counters: objects named over the run (the desk, the chair and the drum: 3).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "../test/profile_caster.h"
#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"
#include "spott_tr_plus/controller/object_recognition.h"

namespace spott_tr_plus::controller {
namespace {

using test_scene::Cast;
using test_scene::kHeadZ;
using test_scene::Solid;

void BM_RecognitionProfile(benchmark::State& state) {
  const auto loaded = spott_map::LoadWorldFile(WORLDS_DIR "/cim_office.yaml");
  if (!loaded.ok()) {
    state.SkipWithError("cim_office.yaml does not load");
    return;
  }
  const spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(*loaded.world);
  const std::vector<Solid> scene = {{{2.5, 1.0}, 0.0, 1.6, 0.8, 0.75, false},
                                    {{2.5, 2.0}, 0.0, 0.5, 0.5, 0.9, false},
                                    {{3.6, 2.0}, 0.0, 0.6, 0.6, 0.9, true}};
  const Vec3 head(2.5, 3.6, kHeadZ);
  // The profiles of one sweep there and back, cast once (casting is not the recognizer's).
  std::vector<std::pair<std::vector<ProfileSample>, bool>> profiles;
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k <= 32; ++k) {
      const double pan = -M_PI / 2 + (pass == 0 ? -0.8 + 0.05 * k : 0.8 - 0.05 * k);
      profiles.emplace_back(Cast(scene, head, pan, false), false);
      profiles.emplace_back(Cast(scene, head, pan, true), true);
    }
  }
  ObjectRecognizer recognizer{RecognitionParameters{}};
  recognizer.SetMap(&db);
  std::size_t i = 0;
  int named = 0, named_last_sweep = 0;
  for (auto _ : state) {
    if (i == profiles.size()) {  // a new look-around: what was seen is forgotten
      named_last_sweep = named;
      named = 0;
      recognizer.Forget();
      i = 0;
    }
    recognizer.AddProfile(head, profiles[i].first, profiles[i].second);
    if (++i % 4 == 0) named += static_cast<int>(recognizer.Take().size());
  }
  state.counters["named_per_sweep"] = named_last_sweep;
}

BENCHMARK(BM_RecognitionProfile)->Iterations(2640)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace spott_tr_plus::controller

BENCHMARK_MAIN();
