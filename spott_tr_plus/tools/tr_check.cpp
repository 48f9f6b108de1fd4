// tr_check FILE...: parses and checks TR+ program files, prints every error and warning located
// as file:line:column and each program's verdict (universal / complete / regression / neither).
// Exit status 0 when no file has an error, 1 otherwise, 2 on bad usage.
#include <iostream>

#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/parser.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: tr_check FILE.tr...\n";
    return 2;
  }
  bool ok = true;
  for (int i = 1; i < argc; ++i) {
    const spott_tr_plus::ParseResult parsed = spott_tr_plus::ParseProgramFile(argv[i]);
    if (!parsed.diagnostics.empty()) {
      std::cout << spott_tr_plus::FormatDiagnostics(parsed.diagnostics) << "\n";
    }
    if (!parsed.ok()) {
      ok = false;
      continue;
    }
    const spott_tr_plus::CheckReport report = spott_tr_plus::CheckProgram(parsed.program);
    if (!report.diagnostics.empty()) {
      std::cout << spott_tr_plus::FormatDiagnostics(report.diagnostics) << "\n";
    }
    std::cout << report.Summary();
    ok = ok && report.ok();
  }
  return ok ? 0 : 1;
}
