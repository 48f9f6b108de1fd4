// Fuzzes the TR+ parser and checker with arbitrary text. Besides crashes and sanitizer
// reports, it checks two properties: every diagnostic is located inside the text, and a
// program that parses prints to text that parses back to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;  // the checker decides coNP-complete questions: keep inputs small
  const std::string text(reinterpret_cast<const char*>(data), size);
  const spott_tr_plus::ParseResult r = spott_tr_plus::ParseProgramText(text, "fuzz.tr");
  int lines = 1;
  for (char c : text) lines += c == '\n';
  for (const auto& d : r.diagnostics) {
    if (d.where.line < 1 || d.where.line > lines || d.where.column < 1) std::abort();
  }
  if (!r.ok()) return 0;
  const std::string printed = spott_tr_plus::ToText(r.program);
  const spott_tr_plus::ParseResult again = spott_tr_plus::ParseProgramText(printed, "again.tr");
  if (!again.ok() || spott_tr_plus::ToText(again.program) != printed) std::abort();
  const spott_tr_plus::CheckReport report = spott_tr_plus::CheckProgram(r.program);
  (void)report.Summary();
  return 0;
}
