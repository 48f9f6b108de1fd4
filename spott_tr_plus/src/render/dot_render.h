// Renders DOT text to PNG or SVG with the Graphviz library (gvc, dot layout). Not part of the
// ROS-free core library: it links libgvc.
#pragma once

#include <string>

namespace spott_tr_plus {

/// Lays out `dot` with the dot engine and writes `path` in `format` ("png", "svg", ...).
/// Returns an empty string on success, else what went wrong.
std::string RenderDot(const std::string& dot, const std::string& format, const std::string& path);

}  // namespace spott_tr_plus
