#include "dot_render.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

namespace spott_tr_plus {

namespace {

// One Graphviz context for the process, never freed: with Debian's graphviz 2.42, gvLayout in a
// second context created after gvFreeContext read freed memory (ASan: heap-use-after-free in a
// strcmp inside graphviz, on the test's second render); with one context it does not.
GVC_t* Context() {
  static GVC_t* const gvc = gvContext();
  return gvc;
}

}  // namespace

std::string RenderDot(const std::string& dot, const std::string& format, const std::string& path) {
  GVC_t* gvc = Context();
  if (!gvc) return "cannot create a Graphviz context";
  Agraph_t* g = agmemread(dot.c_str());
  if (!g) return "Graphviz cannot read the DOT text";
  std::string error;
  if (gvLayout(gvc, g, "dot") != 0) {
    error = "Graphviz layout failed";
  } else {
    if (gvRenderFilename(gvc, g, format.c_str(), path.c_str()) != 0) {
      error = "Graphviz cannot render " + format + " to " + path;
    }
    gvFreeLayout(gvc, g);
  }
  agclose(g);
  return error;
}

}  // namespace spott_tr_plus
