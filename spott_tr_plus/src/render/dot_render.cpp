#include "dot_render.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

namespace spott_tr_plus {

std::string RenderDot(const std::string& dot, const std::string& format, const std::string& path) {
  GVC_t* gvc = gvContext();
  if (!gvc) return "cannot create a Graphviz context";
  Agraph_t* g = agmemread(dot.c_str());
  if (!g) {
    gvFreeContext(gvc);
    return "Graphviz cannot read the DOT text";
  }
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
  gvFreeContext(gvc);
  return error;
}

}  // namespace spott_tr_plus
