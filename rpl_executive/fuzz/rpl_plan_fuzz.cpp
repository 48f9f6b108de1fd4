// Fuzzes the RPL reader and checker with arbitrary text. Besides crashes and sanitizer reports it
// checks two properties: every diagnostic is located inside the text, and data that read print
// to text that reads back to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "rpl_executive/rpl/office_robot.h"
#include "rpl_executive/rpl/plan.h"
#include "rpl_executive/rpl/reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace rpl_executive::rpl;
  if (size > 8192) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  int lines = 1;
  for (char c : text) lines += c == '\n';
  const ReadResult read = ReadPlanText(text, "fuzz.rpl");
  if (read.ok()) {
    std::string printed;
    for (const auto& d : read.forms) printed += PrintDatum(d) + "\n";
    const ReadResult again = ReadPlanText(printed, "again.rpl");
    if (!again.ok()) std::abort();
    std::string reprinted;
    for (const auto& d : again.forms) reprinted += PrintDatum(d) + "\n";
    if (reprinted != printed) std::abort();
  }
  static const Vocabulary vocabulary = [] {
    Vocabulary v = office::OfficeVocabulary();
    v.functions.push_back({"TRACE", 1, -1, ""});
    v.modules.push_back({"ARM", 0, 1, {"GRIPPER"}, ""});
    v.valves.push_back("GRIPPER");
    return v;
  }();
  const CompileResult r = CompilePlan(text, "fuzz.rpl", vocabulary);
  for (const auto& d : r.diagnostics) {
    if (d.where.line < 1 || d.where.line > lines || d.where.column < 1) std::abort();
    if (d.file != "fuzz.rpl" || d.message.empty()) std::abort();
  }
  if (r.ok() == HasErrors(r.diagnostics)) std::abort();
  return 0;
}
