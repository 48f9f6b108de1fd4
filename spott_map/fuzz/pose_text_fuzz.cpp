// Fuzzes the "x y yaw" pose text: any text gives a finite pose or an error that says why.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spott_map/pose_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const auto pose = spott_map::ParsePoseText(text, &error);
  if (pose) {
    if (!std::isfinite(pose->x) || !std::isfinite(pose->y) || !std::isfinite(pose->yaw))
      std::abort();
  } else if (error.empty()) {
    std::abort();
  }
  return 0;
}
