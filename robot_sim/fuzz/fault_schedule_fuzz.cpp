// Fuzzes the fault schedule parser (the `faults` parameter of the node).
#include <cstddef>
#include <cstdint>
#include <string>

#include "robot_sim/fault_events.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto r = robot_sim::ParseFaultSchedule(input, "fuzz.yaml");
  if (r.ok()) {
    volatile std::size_t n = r.events.size();
    (void)n;
  }
  return 0;
}
