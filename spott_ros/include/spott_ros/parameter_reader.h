// The one way a SPOTT-ROS node reads its parameters: typed getters over the node's private
// namespace, every violation collected (wrong type, out of range, unknown key) and returned at
// once, so that a misspelt or mistyped key in a YAML file stops the node with its name instead
// of silently keeping a default (Nav2 refuses bad parameters at configure time the same way).
//
// Keys are paths below the private namespace ("window/resolution_m"). Units are part of the
// names (CONTRIBUTING.md: section/name_unit, REP-103 units); a getter's `unit` only says it
// again in error messages. Typical use:
//
//   spott_ros::ParameterReader r = spott_ros::ParameterReader::FromNode(pnh);
//   r.Get("cycle_rate_hz", p.cycle_rate_hz, "Hz");
//   r.Get("window/resolution_m", p.window.resolution_m, "m");
//   for (const std::string& e : ValidateParameters(p)) r.Fail(e);   // the core's own checks
//   const std::vector<std::string> problems = r.Finish();          // + every unknown key
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

namespace ros {
class NodeHandle;
}

namespace spott_ros {

class ParameterReader {
 public:
  /// `values`: the private namespace as an XmlRpc struct (invalid or empty: nothing set).
  /// `prefix` is how keys are named in messages ("~" for a node's private namespace).
  explicit ParameterReader(XmlRpc::XmlRpcValue values, std::string prefix = "~");
  /// Every parameter under `pnh`'s namespace (a private node handle, "~").
  static ParameterReader FromNode(const ros::NodeHandle& pnh);

  /// Leave `value` as it is when `key` is absent; a violation when present with another type.
  /// Integers are accepted where a double is asked for.
  void Get(const std::string& key, double& value, const std::string& unit = "");
  void Get(const std::string& key, int& value, const std::string& unit = "");
  void Get(const std::string& key, bool& value);
  void Get(const std::string& key, std::string& value);
  void Get(const std::string& key, std::vector<double>& value, const std::string& unit = "");
  void Get(const std::string& key, std::vector<std::string>& value);
  /// A double given in degrees in the file, stored in radians.
  void GetDegrees(const std::string& key, double& radians);
  /// A key renamed in this release: read under `old_key` when only that is set (with a
  /// deprecation warning in Warnings()), else under `key`.
  void GetRenamed(const std::string& key, const std::string& old_key, double& value,
                  const std::string& unit = "");

  /// True when `key` is set (marks nothing as read).
  bool Has(const std::string& key) const;
  /// The names directly below `section` ("" = the top), e.g. the source names of an arbiter.
  std::vector<std::string> Keys(const std::string& section) const;
  /// Marks `key` and everything below it as known without reading it (read by other code).
  void Accept(const std::string& key);

  /// A violation found by the caller (a core's ValidateParameters message): recorded as is,
  /// prefixed with the reader's prefix when it starts with a key name.
  void Fail(const std::string& message);
  /// Range checks that name the key: a violation "~key must be <what> (got <value>)".
  void Require(bool ok, const std::string& key, const std::string& what, double value);

  /// Every violation so far plus every key that no getter asked for, sorted by key.
  std::vector<std::string> Finish();
  /// Deprecation warnings (renamed keys used under their old names).
  const std::vector<std::string>& Warnings() const { return warnings_; }

 private:
  const XmlRpc::XmlRpcValue* Find(const std::string& key) const;
  void Known(const std::string& key);
  void WrongType(const std::string& key, const XmlRpc::XmlRpcValue& v, const std::string& want);
  void CollectUnknown(const XmlRpc::XmlRpcValue& v, const std::string& path,
                      std::vector<std::string>& out) const;

  XmlRpc::XmlRpcValue values_;
  std::string prefix_;
  std::set<std::string> known_;  ///< Keys read (and sections accepted whole).
  std::vector<std::string> violations_;
  std::vector<std::string> warnings_;
};

/// Reads, validates and returns a node's parameters, or logs every problem (ROS_FATAL) and
/// returns nullopt: the node then exits with status 1. `read` fills the struct from the reader.
template <class Params, class ReadFn>
std::optional<Params> ReadNodeParameters(const ros::NodeHandle& pnh, const char* node, ReadFn read);

}  // namespace spott_ros

#include "spott_ros/parameter_reader_impl.h"
