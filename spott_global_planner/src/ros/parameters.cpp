#include "spott_global_planner/ros/parameters.h"

#include <set>
#include <sstream>

namespace spott_global_planner::ros_parameters {

namespace {

using XmlRpc::XmlRpcValue;

class Reader {
 public:
  Reader(XmlRpcValue& root, std::vector<std::string>& violations)
      : root_(root), violations_(violations) {}

  void Number(const std::string& name, double& out) {
    XmlRpcValue* v = Find(name);
    if (!v) return;
    if (v->getType() == XmlRpcValue::TypeDouble) {
      out = static_cast<double>(*v);
    } else if (v->getType() == XmlRpcValue::TypeInt) {
      out = static_cast<int>(*v);
    } else {
      violations_.push_back("~" + name + " must be a number");
    }
  }
  void Integer(const std::string& name, int& out) {
    XmlRpcValue* v = Find(name);
    if (!v) return;
    if (v->getType() == XmlRpcValue::TypeInt) {
      out = static_cast<int>(*v);
    } else {
      violations_.push_back("~" + name + " must be an integer");
    }
  }
  void Boolean(const std::string& name, bool& out) {
    XmlRpcValue* v = Find(name);
    if (!v) return;
    if (v->getType() == XmlRpcValue::TypeBoolean) {
      out = static_cast<bool>(*v);
    } else {
      violations_.push_back("~" + name + " must be true or false");
    }
  }
  void String(const std::string& name, std::string& out) {
    XmlRpcValue* v = Find(name);
    if (!v) return;
    if (v->getType() == XmlRpcValue::TypeString) {
      out = static_cast<std::string>(*v);
    } else {
      violations_.push_back("~" + name + " must be a string");
    }
  }

  /// Every name below `root` that no reader asked for.
  void ReportUnknown() { Unknown(root_, ""); }

 private:
  XmlRpcValue* Find(const std::string& name) {
    known_.insert(name);
    XmlRpcValue* v = &root_;
    std::size_t start = 0;
    while (true) {
      const std::size_t slash = name.find('/', start);
      const std::string part = name.substr(start, slash - start);
      if (v->getType() != XmlRpcValue::TypeStruct || !v->hasMember(part)) return nullptr;
      v = &(*v)[part];
      if (slash == std::string::npos) return v;
      known_.insert(name.substr(0, slash));
      start = slash + 1;
    }
  }
  void Unknown(XmlRpcValue& v, const std::string& prefix) {
    if (v.getType() != XmlRpcValue::TypeStruct) return;
    for (auto& [key, child] : v) {
      const std::string name = prefix + key;
      if (!known_.count(name)) {
        violations_.push_back("~" + name + " is not a parameter of global_planner");
      } else {
        Unknown(child, name + "/");
      }
    }
  }

  XmlRpcValue& root_;
  std::vector<std::string>& violations_;
  std::set<std::string> known_;
};

}  // namespace

std::vector<std::string> ReadParameters(XmlRpcValue& params, NodeParameters& p) {
  std::vector<std::string> v;
  if (params.valid() && params.getType() != XmlRpcValue::TypeStruct) {
    v.push_back("~ (the private namespace) must hold named parameters");
    return v;
  }
  Reader r(params, v);
  r.String("frame_id", p.frame_id);
  r.String("robot_frame", p.robot_frame);
  r.Number("update_rate", p.update_rate_hz);
  r.Boolean("follow_local_window", p.follow_local_window);
  std::string algorithm = ToString(p.core.algorithm);
  r.String("algorithm", algorithm);
  if (const auto a = ParseSearchAlgorithm(algorithm)) {
    p.core.algorithm = *a;
  } else {
    v.push_back("~algorithm must be dijkstra or astar (got '" + algorithm + "')");
  }
  WindowParameters& w = p.core.window;
  r.Number("window/window_size_m", w.window_size_m);
  r.Number("window/resolution_m", w.resolution_m);
  r.Number("window/recentre_margin_m", w.recentre_margin_m);
  r.Boolean("window/fit_node", w.fit_node);
  r.Number("window/max_window_size_m", w.max_window_size_m);
  r.Boolean("detect_blocked_passages", p.core.detect_blocked_passages);
  PassageParameters& s = p.core.passage;
  r.Number("passage/resolution_m", s.resolution_m);
  r.Number("passage/padding_m", s.padding_m);
  r.Number("passage/door_depth_m", s.door_depth_m);
  r.Integer("passage/max_cells", s.max_cells);
  r.ReportUnknown();
  if (p.frame_id.empty()) v.push_back("~frame_id must not be empty");
  if (p.robot_frame.empty()) v.push_back("~robot_frame must not be empty");
  if (!(p.update_rate_hz > 0.0 && p.update_rate_hz <= 100.0)) {
    std::ostringstream out;
    out << "~update_rate must be in (0, 100] Hz (got " << p.update_rate_hz << ")";
    v.push_back(out.str());
  }
  for (const std::string& s : ValidateParameters(p.core)) v.push_back("~" + s);
  return v;
}

}  // namespace spott_global_planner::ros_parameters
