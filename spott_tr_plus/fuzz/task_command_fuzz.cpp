// Fuzzes the task-command parser and interpreter. Properties: diagnostics are located on line 1
// inside the text, a parsed command prints to text that parses back to the same text, and
// interpretation never yields a non-finite goal.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spott_tr_plus/task_command.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 1024) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const spott_tr_plus::TaskParseResult r = spott_tr_plus::ParseTaskCommand(text);
  for (const auto& d : r.diagnostics) {
    if (d.where.line < 1 || d.where.column < 1) std::abort();
  }
  if (!r.ok()) return 0;
  const std::string printed = spott_tr_plus::ToText(*r.command);
  const spott_tr_plus::TaskParseResult again = spott_tr_plus::ParseTaskCommand(printed);
  if (!again.ok() || spott_tr_plus::ToText(*again.command) != printed) std::abort();
  const spott_tr_plus::TaskInterpretResult in =
      spott_tr_plus::InterpretTask(*r.command, 1.0, 2.0, 0.5, {});
  if (in.ok()) {
    const auto& i = *in.interpretation;
    if (i.goal && !(std::isfinite(i.goal->goal_x) && std::isfinite(i.goal->goal_y))) {
      std::abort();
    }
    const auto b = i.bias.At(0.0, 0.0, 0.0);
    (void)b;
  }
  return 0;
}
