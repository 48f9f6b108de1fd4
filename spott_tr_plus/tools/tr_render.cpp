// tr_render FILE.tr OUT_DIR [png|svg]: checks a TR+ program file and writes, for each program,
// its TR tree (NAME_tree.dot and .png/.svg) and TR sequence (NAME_sequence.dot and .png/.svg),
// and the whole file's trees (all_trees.dot/.png). Exit status 1 on any error.
#include <fstream>
#include <iostream>

#include "../src/render/dot_render.h"
#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/dot_export.h"
#include "spott_tr_plus/parser.h"

namespace {

bool Write(const std::string& dot, const std::string& base, const std::string& format) {
  std::ofstream(base + ".dot") << dot;
  const std::string error = spott_tr_plus::RenderDot(dot, format, base + "." + format);
  if (!error.empty()) std::cerr << base << ": " << error << "\n";
  return error.empty();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: tr_render FILE.tr OUT_DIR [png|svg]\n";
    return 2;
  }
  const std::string format = argc > 3 ? argv[3] : "png";
  const spott_tr_plus::ParseResult parsed = spott_tr_plus::ParseProgramFile(argv[1]);
  if (!parsed.ok()) {
    std::cerr << spott_tr_plus::FormatDiagnostics(parsed.diagnostics) << "\n";
    return 1;
  }
  const spott_tr_plus::CheckReport report = spott_tr_plus::CheckProgram(parsed.program);
  if (!report.diagnostics.empty()) {
    std::cerr << spott_tr_plus::FormatDiagnostics(report.diagnostics) << "\n";
  }
  if (!report.ok()) return 1;
  const std::string dir = argv[2];
  bool ok = true;
  for (const auto& p : parsed.program.programs) {
    const auto* v = report.Find(p.name);
    ok = Write(spott_tr_plus::TrTreeDot(p, v->parent), dir + "/" + p.name + "_tree", format) && ok;
    ok = Write(spott_tr_plus::TrSequenceDot(p), dir + "/" + p.name + "_sequence", format) && ok;
  }
  ok = Write(spott_tr_plus::ProgramFileDot(parsed.program, report), dir + "/all_trees", format) &&
       ok;
  std::cout << report.Summary();
  return ok ? 0 : 1;
}
