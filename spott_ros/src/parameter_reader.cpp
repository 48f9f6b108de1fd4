#include "spott_ros/parameter_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <ros/node_handle.h>
#include <ros/this_node.h>

namespace spott_ros {
namespace {

using XmlRpc::XmlRpcValue;

std::vector<std::string> Split(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '/'))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string TypeName(const XmlRpcValue& v) {
  switch (v.getType()) {
    case XmlRpcValue::TypeBoolean:
      return "true/false";
    case XmlRpcValue::TypeInt:
      return "an integer";
    case XmlRpcValue::TypeDouble:
      return "a number";
    case XmlRpcValue::TypeString:
      return "a string";
    case XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpcValue::TypeStruct:
      return "a section";
    default:
      return "a value of another kind";
  }
}

std::string WithUnit(const std::string& what, const std::string& unit) {
  return unit.empty() ? what : what + " (" + unit + ")";
}

bool AsDouble(const XmlRpcValue& v, double& out) {
  XmlRpcValue copy = v;  // XmlRpcValue's conversions are non-const
  if (v.getType() == XmlRpcValue::TypeDouble) {
    out = static_cast<double>(copy);
    return true;
  }
  if (v.getType() == XmlRpcValue::TypeInt) {
    out = static_cast<int>(copy);
    return true;
  }
  return false;
}

}  // namespace

ParameterReader::ParameterReader(XmlRpc::XmlRpcValue values, std::string prefix)
    : values_(std::move(values)), prefix_(std::move(prefix)) {}

ParameterReader ParameterReader::FromNode(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue values;  // stays invalid (nothing set) when the namespace is empty
  pnh.getParam(pnh.getNamespace(), values);
  return ParameterReader(values, "~");
}

const XmlRpc::XmlRpcValue* ParameterReader::Find(const std::string& key) const {
  const XmlRpcValue* v = &values_;
  for (const std::string& part : Split(key)) {
    if (v->getType() != XmlRpcValue::TypeStruct || !v->hasMember(part)) return nullptr;
    v = &(*v)[part];
  }
  return v == &values_ ? nullptr : v;
}

void ParameterReader::Known(const std::string& key) {
  std::string path;
  for (const std::string& part : Split(key)) {
    path += (path.empty() ? "" : "/") + part;
    known_.insert(path + "/");  // the sections on the way are known as sections
  }
  known_.insert(path);
}

void ParameterReader::WrongType(const std::string& key, const XmlRpc::XmlRpcValue& v,
                                const std::string& want) {
  violations_.push_back(prefix_ + key + " must be " + want + ", not " + TypeName(v));
}

void ParameterReader::Get(const std::string& key, double& value, const std::string& unit) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  double d;
  if (!AsDouble(*v, d)) return WrongType(key, *v, WithUnit("a number", unit));
  if (!std::isfinite(d)) {
    violations_.push_back(prefix_ + key + " must be finite");
    return;
  }
  value = d;
}

void ParameterReader::Get(const std::string& key, int& value, const std::string& unit) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  if (v->getType() != XmlRpcValue::TypeInt) return WrongType(key, *v, WithUnit("an integer", unit));
  XmlRpcValue copy = *v;
  value = static_cast<int>(copy);
}

void ParameterReader::Get(const std::string& key, bool& value) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  if (v->getType() != XmlRpcValue::TypeBoolean) return WrongType(key, *v, "true or false");
  XmlRpcValue copy = *v;
  value = static_cast<bool>(copy);
}

void ParameterReader::Get(const std::string& key, std::string& value) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  if (v->getType() != XmlRpcValue::TypeString) return WrongType(key, *v, "a string");
  XmlRpcValue copy = *v;
  value = static_cast<std::string>(copy);
}

void ParameterReader::Get(const std::string& key, std::vector<double>& value,
                          const std::string& unit) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  if (v->getType() != XmlRpcValue::TypeArray)
    return WrongType(key, *v, WithUnit("a list of numbers", unit));
  std::vector<double> out;
  for (int i = 0; i < v->size(); ++i) {
    double d;
    if (!AsDouble((*v)[i], d) || !std::isfinite(d)) {
      violations_.push_back(prefix_ + key + "[" + std::to_string(i) +
                            "] must be a finite number, not " + TypeName((*v)[i]));
      return;
    }
    out.push_back(d);
  }
  value = out;
}

void ParameterReader::Get(const std::string& key, std::vector<std::string>& value) {
  Known(key);
  const XmlRpcValue* v = Find(key);
  if (!v) return;
  if (v->getType() != XmlRpcValue::TypeArray) return WrongType(key, *v, "a list of strings");
  std::vector<std::string> out;
  for (int i = 0; i < v->size(); ++i) {
    if ((*v)[i].getType() != XmlRpcValue::TypeString) {
      violations_.push_back(prefix_ + key + "[" + std::to_string(i) + "] must be a string, not " +
                            TypeName((*v)[i]));
      return;
    }
    XmlRpcValue copy = (*v)[i];
    out.push_back(static_cast<std::string>(copy));
  }
  value = out;
}

void ParameterReader::GetDegrees(const std::string& key, double& radians) {
  double degrees = radians * 180.0 / M_PI;
  Get(key, degrees, "deg");
  // Beyond about 1e306 degrees the conversion overflows to infinity (a parameter fuzzer's
  // finding): refused as any non-finite number is.
  if (!std::isfinite(degrees * M_PI / 180.0)) {
    violations_.push_back(prefix_ + key + " must be finite in radians too");
    return;
  }
  radians = degrees * M_PI / 180.0;
}

void ParameterReader::GetRenamed(const std::string& key, const std::string& old_key, double& value,
                                 const std::string& unit) {
  if (Has(old_key) && !Has(key)) {
    warnings_.push_back(prefix_ + old_key + " is deprecated: call it " + prefix_ + key);
    Known(key);
    Get(old_key, value, unit);
    return;
  }
  Known(old_key);
  if (Has(old_key)) {
    warnings_.push_back(prefix_ + old_key + " is ignored: " + prefix_ + key + " is set");
  }
  Get(key, value, unit);
}

bool ParameterReader::Has(const std::string& key) const { return Find(key) != nullptr; }

std::vector<std::string> ParameterReader::Keys(const std::string& section) const {
  const XmlRpcValue* v = section.empty() ? &values_ : Find(section);
  std::vector<std::string> keys;
  if (!v || v->getType() != XmlRpcValue::TypeStruct) return keys;
  for (auto it = v->begin(); it != v->end(); ++it) keys.push_back(it->first);
  return keys;
}

void ParameterReader::Accept(const std::string& key) {
  Known(key);
  known_.insert(key + "/*");
}

void ParameterReader::Fail(const std::string& message) {
  violations_.push_back(message.rfind(prefix_, 0) == 0 ? message : prefix_ + message);
}

void ParameterReader::Require(bool ok, const std::string& key, const std::string& what,
                              double value) {
  if (ok) return;
  std::ostringstream out;
  out << prefix_ << key << " must be " << what << " (got " << value << ")";
  violations_.push_back(out.str());
}

void ParameterReader::CollectUnknown(const XmlRpc::XmlRpcValue& v, const std::string& path,
                                     std::vector<std::string>& out) const {
  if (!path.empty() && known_.count(path + "/*")) return;  // accepted whole
  if (v.getType() == XmlRpcValue::TypeStruct && (path.empty() || known_.count(path + "/"))) {
    for (auto it = v.begin(); it != v.end(); ++it) {
      CollectUnknown(it->second, path.empty() ? it->first : path + "/" + it->first, out);
    }
    return;
  }
  if (!known_.count(path)) out.push_back(prefix_ + path + " is not a parameter of this node");
}

std::vector<std::string> ParameterReader::Finish() {
  std::vector<std::string> all = violations_;
  std::vector<std::string> unknown;
  if (values_.getType() == XmlRpcValue::TypeStruct) CollectUnknown(values_, "", unknown);
  std::sort(unknown.begin(), unknown.end());
  all.insert(all.end(), unknown.begin(), unknown.end());
  return all;
}

}  // namespace spott_ros
