#include "parameter_fuzz.h"

#include <ros/duration.h>
#include <yaml-cpp/yaml.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <limits>
#include <sstream>

namespace spott_fuzz {
namespace {

using XmlRpc::XmlRpcValue;

XmlRpcValue EmptyStruct() {
  XmlRpcValue v;
  v.begin();  // an invalid value becomes an empty struct
  return v;
}

XmlRpcValue EmptyArray() {
  XmlRpcValue v;
  v.setSize(0);
  return v;
}

// A YAML scalar typed as rosparam (PyYAML) types it; quoted scalars stay strings.
XmlRpcValue FromYamlScalar(const YAML::Node& n) {
  const std::string text = n.Scalar();
  if (n.Tag() != "!") {
    int i;
    double d;
    bool b;
    if (YAML::convert<int>::decode(n, i)) return XmlRpcValue(i);
    if (YAML::convert<double>::decode(n, d)) return XmlRpcValue(d);
    if (YAML::convert<bool>::decode(n, b)) return XmlRpcValue(b);
  }
  return XmlRpcValue(text);
}

XmlRpcValue FromYaml(const YAML::Node& n, const std::string& path, ParameterVocabulary& v) {
  switch (n.Type()) {
    case YAML::NodeType::Map: {
      XmlRpcValue s = EmptyStruct();
      if (!path.empty()) v.sections.push_back(path);
      for (const auto& kv : n) {
        const std::string key = kv.first.as<std::string>();
        const std::string child = path.empty() ? key : path + "/" + key;
        s[key] = FromYaml(kv.second, child, v);
        if (!kv.second.IsMap()) v.keys.push_back(child);
      }
      return s;
    }
    case YAML::NodeType::Sequence: {
      XmlRpcValue a = EmptyArray();
      int i = 0;
      for (const auto& item : n) a[i++] = FromYaml(item, path, v);
      return a;
    }
    case YAML::NodeType::Scalar: {
      XmlRpcValue s = FromYamlScalar(n);
      if (s.getType() == XmlRpcValue::TypeString) v.words.push_back(static_cast<std::string>(s));
      return s;
    }
    default:
      return XmlRpcValue();
  }
}

const XmlRpcValue* last_tree = nullptr;  // printed with a finding

// ---- values ----------------------------------------------------------------------------------

double Number(FuzzedDataProvider& in) {
  static const double kSpecial[] = {0.0,
                                    -0.0,
                                    1.0,
                                    -1.0,
                                    0.5,
                                    2.0,
                                    0.1,
                                    10.0,
                                    100.0,
                                    1000.0,
                                    1e4,
                                    1e6,
                                    1e9,
                                    1e-6,
                                    1e-9,
                                    1e-300,
                                    -1e-300,
                                    5e-324,
                                    1e300,
                                    -1e300,
                                    DBL_MAX,
                                    -DBL_MAX,
                                    std::numeric_limits<double>::quiet_NaN(),
                                    -std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    M_PI,
                                    M_PI / 2,
                                    2 * M_PI,
                                    180.0,
                                    360.0,
                                    2147483647.0,
                                    2147483648.0,
                                    4294967296.0,
                                    1e18};
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
    case 1:
      return in.PickValueInArray(kSpecial);
    case 2:
      return in.ConsumeFloatingPoint<double>();
    default: {
      const uint64_t bits = in.ConsumeIntegral<uint64_t>();
      double d;
      static_assert(sizeof d == sizeof bits, "double is 64 bits");
      __builtin_memcpy(&d, &bits, sizeof d);
      return d;
    }
  }
}

int Integer(FuzzedDataProvider& in) {
  static const int kSpecial[] = {0,       1,           -1,         2,       3,           4,
                                 8,       24,          100,        255,     256,         1000,
                                 10000,   65535,       1 << 20,    1 << 24, INT_MAX - 1, INT_MAX,
                                 INT_MIN, INT_MIN + 1, -100000000, 1 << 30};
  return in.ConsumeBool() ? in.PickValueInArray(kSpecial) : in.ConsumeIntegral<int>();
}

std::string Word(FuzzedDataProvider& in, const ParameterVocabulary& v) {
  static const char* kSpecial[] = {"",    " ",   "~",         "*",       "/",        "a/b",
                                   "x",   "_",   "0",         "nan",     "inf",      "-inf",
                                   "1e9", "-1",  "0 0 0",     "1 2 nan", "1 2 3 4",  "true",
                                   "map", "map", "base_link", "odom",    "\xff\xfe", "a b"};
  switch (in.ConsumeIntegralInRange(0, 4)) {
    case 0:
      if (!v.words.empty())
        return v.words[in.ConsumeIntegralInRange<size_t>(0, v.words.size() - 1)];
      [[fallthrough]];
    case 1:
      return in.PickValueInArray(kSpecial);
    case 2:
      if (!v.keys.empty()) {  // a key's last name as a value (or a made-up key's name)
        const std::string& k = v.keys[in.ConsumeIntegralInRange<size_t>(0, v.keys.size() - 1)];
        return k.substr(k.rfind('/') + 1);
      }
      [[fallthrough]];
    case 3:
      return in.ConsumeRandomLengthString(24);
    default:
      return std::string(in.ConsumeIntegralInRange(100, 5000), 'a');
  }
}

XmlRpcValue Value(FuzzedDataProvider& in, const ParameterVocabulary& v, int depth) {
  switch (in.ConsumeIntegralInRange(0, 12)) {
    case 0:
      return XmlRpcValue(in.ConsumeBool());
    case 1:
    case 2:
      return XmlRpcValue(Integer(in));
    case 3:
    case 4:
    case 5:
      return XmlRpcValue(Number(in));
    case 6:
    case 7:
      return XmlRpcValue(Word(in, v));
    case 8: {  // a list, often of numbers or strings (the lists the nodes read)
      XmlRpcValue a = EmptyArray();
      const int n = in.ConsumeIntegralInRange(0, depth < 3 ? 6 : 0);
      const int kind = in.ConsumeIntegralInRange(0, 2);
      for (int i = 0; i < n; ++i) {
        a[i] = kind == 0   ? XmlRpcValue(Number(in))
               : kind == 1 ? XmlRpcValue(Word(in, v))
                           : Value(in, v, depth + 1);
      }
      return a;
    }
    case 9: {  // a section
      XmlRpcValue s = EmptyStruct();
      const int n = in.ConsumeIntegralInRange(0, depth < 3 ? 4 : 0);
      for (int i = 0; i < n; ++i) s[Word(in, v)] = Value(in, v, depth + 1);
      return s;
    }
    case 10: {  // a date (XmlRpc's dateTime.iso8601)
      struct tm t = {};
      t.tm_year = in.ConsumeIntegralInRange(-1900, 8000);
      t.tm_mon = in.ConsumeIntegralInRange(0, 11);
      t.tm_mday = in.ConsumeIntegralInRange(1, 31);
      return XmlRpcValue(&t);
    }
    case 11: {  // binary (XmlRpc's base64)
      std::string bytes = in.ConsumeRandomLengthString(16);
      return XmlRpcValue(static_cast<void*>(bytes.data()), static_cast<int>(bytes.size()));
    }
    default:
      return XmlRpcValue();  // invalid (XmlRpc's nil)
  }
}

// A number moved to where ranges end: scaled, negated, the next double, the other numeric type.
XmlRpcValue Nudged(FuzzedDataProvider& in, const XmlRpcValue& old) {
  double d;
  XmlRpcValue copy = old;
  if (old.getType() == XmlRpcValue::TypeDouble) {
    d = static_cast<double>(copy);
  } else if (old.getType() == XmlRpcValue::TypeInt) {
    d = static_cast<int>(copy);
  } else {
    return XmlRpcValue(Number(in));
  }
  static const double kFactor[] = {-1.0, 0.0, 0.5, 2.0, 10.0, 0.1, 1e3, 1e-3, 1e10, 1e-10, 1e300};
  switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0:
      d *= in.PickValueInArray(kFactor);
      break;
    case 1:
      d = std::nextafter(d, in.ConsumeBool() ? INFINITY : -INFINITY);
      break;
    case 2:
      d = d != 0.0 ? 1.0 / d : 0.0;
      break;
    case 3:
      d += in.ConsumeIntegralInRange(-3, 3);
      break;
    case 4:  // an integer where a number was, and the converse
      if (old.getType() == XmlRpcValue::TypeInt) return XmlRpcValue(d);
      if (std::fabs(d) < 2e9) return XmlRpcValue(static_cast<int>(d));
      return XmlRpcValue(Integer(in));
    case 5:
      d = d * 180.0 / M_PI;  // degrees given for radians
      break;
    default:
      d = std::ldexp(d, in.ConsumeIntegralInRange(-64, 64));
  }
  if (old.getType() == XmlRpcValue::TypeInt && std::fabs(d) < 2e9 && in.ConsumeBool())
    return XmlRpcValue(static_cast<int>(d));
  return XmlRpcValue(d);
}

// ---- paths -----------------------------------------------------------------------------------

std::vector<std::string> Split(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream s(path);
  while (std::getline(s, part, '/')) parts.push_back(part);
  return parts;
}

// A key's path as the names of its sections (a name may be empty or hold a '/': the parameter
// server would not make those, a struct in memory can).
std::vector<std::string> Path(FuzzedDataProvider& in, const ParameterVocabulary& v) {
  const auto pick = [&in](const std::vector<std::string>& list) {
    return list[in.ConsumeIntegralInRange<size_t>(0, list.size() - 1)];
  };
  switch (in.ConsumeIntegralInRange(0, 7)) {
    case 0:
    case 1:
    case 2:
      if (!v.keys.empty()) return Split(pick(v.keys));
      break;
    case 3:
      if (!v.sections.empty()) return Split(pick(v.sections));
      break;
    case 4: {  // a new key below a section or a leaf
      std::vector<std::string> p =
          Split(in.ConsumeBool() || v.keys.empty() ? (v.sections.empty() ? "" : pick(v.sections))
                                                   : pick(v.keys));
      p.push_back(Word(in, v));
      return p;
    }
    case 5:  // a raw name, '/' and all
      return {Word(in, v)};
    default:
      break;
  }
  std::vector<std::string> p;
  const int n = in.ConsumeIntegralInRange(1, 3);
  for (int i = 0; i < n; ++i) p.push_back(Word(in, v));
  return p;
}

// The value at `path`, made (sections on the way become sections) when `create`.
XmlRpcValue* At(XmlRpcValue& root, const std::vector<std::string>& path, bool create) {
  XmlRpcValue* node = &root;
  for (const std::string& name : path) {
    if (node->getType() != XmlRpcValue::TypeStruct) {
      if (!create) return nullptr;
      *node = EmptyStruct();
    }
    if (!create && !node->hasMember(name)) return nullptr;
    node = &(*node)[name];
  }
  return node;
}

void Erase(XmlRpcValue& root, const std::vector<std::string>& path) {
  if (path.empty()) return;
  XmlRpcValue* parent = At(root, {path.begin(), path.end() - 1}, false);
  if (!parent || parent->getType() != XmlRpcValue::TypeStruct) return;
  XmlRpcValue kept = EmptyStruct();
  for (auto it = parent->begin(); it != parent->end(); ++it) {
    if (it->first != path.back()) kept[it->first] = it->second;
  }
  *parent = kept;
}

// ---- printing --------------------------------------------------------------------------------

std::string Quoted(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

void Print(const XmlRpcValue& v, std::ostringstream& out, int indent) {
  const std::string pad(indent, ' ');
  XmlRpcValue copy = v;
  switch (v.getType()) {
    case XmlRpcValue::TypeStruct:
      if (v.size() == 0) out << "{}";
      for (auto it = v.begin(); it != v.end(); ++it) {
        out << "\n" << pad << Quoted(it->first) << ":";
        if (it->second.getType() != XmlRpcValue::TypeStruct) out << " ";
        Print(it->second, out, indent + 2);
      }
      break;
    case XmlRpcValue::TypeArray:
      out << "[";
      for (int i = 0; i < v.size(); ++i) {
        if (i) out << ", ";
        Print(v[i], out, indent + 2);
      }
      out << "]";
      break;
    case XmlRpcValue::TypeBoolean:
      out << (static_cast<bool>(copy) ? "true" : "false");
      break;
    case XmlRpcValue::TypeInt:
      out << static_cast<int>(copy);
      break;
    case XmlRpcValue::TypeDouble: {
      const double d = copy;
      if (std::isnan(d)) {
        out << ".nan";
      } else if (std::isinf(d)) {
        out << (d > 0 ? ".inf" : "-.inf");
      } else {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", d);
        out << text;
        if (std::string(text).find_first_of(".en") == std::string::npos) out << ".0";
      }
      break;
    }
    case XmlRpcValue::TypeString:
      out << Quoted(static_cast<std::string>(copy));
      break;
    case XmlRpcValue::TypeDateTime:
      out << "!!timestamp (a date)";
      break;
    case XmlRpcValue::TypeBase64:
      out << "!!binary (" << v.size() << " bytes)";
      break;
    default:
      out << "~";
  }
}

[[noreturn]] void Finding(const std::string& what) {
  std::cerr << "\n=== parameter fuzz finding: " << what << "\n";
  if (last_tree) std::cerr << "parameters (the node's private namespace):" << ToYaml(*last_tree);
  std::cerr << "\n===" << std::endl;
  std::abort();
}

double Bound(std::string text) {
  text.erase(0, text.find_first_not_of(' '));
  text.erase(text.find_last_not_of(' ') + 1);
  double sign = 1.0;
  if (!text.empty() && text[0] == '-') {
    sign = -1.0;
    text.erase(0, 1);
  }
  if (text == "inf") return sign * INFINITY;
  if (text == "pi") return sign * M_PI;
  if (text == "pi/2") return sign * M_PI / 2;
  if (text == "2pi") return sign * 2 * M_PI;
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') Finding("bad range bound '" + text + "' in a check");
  return sign * d;
}

std::string Text(double d) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", d);
  return text;
}

}  // namespace

ParameterVocabulary LoadVocabulary(const std::string& yaml_file,
                                   const std::vector<std::pair<std::string, std::string>>& launch,
                                   const std::vector<std::string>& extra_keys,
                                   const std::vector<std::string>& extra_words) {
  ParameterVocabulary v;
  try {
    v.config = FromYaml(YAML::LoadFile(yaml_file), "", v);
  } catch (const std::exception& e) {
    std::cerr << "parameter fuzz: cannot read " << yaml_file << ": " << e.what() << std::endl;
    std::abort();
  }
  if (v.config.getType() != XmlRpcValue::TypeStruct) v.config = EmptyStruct();
  for (const auto& [key, value] : launch) {
    *At(v.config, Split(key), true) = XmlRpcValue(value);
    v.keys.push_back(key);
    v.words.push_back(value);
  }
  v.keys.insert(v.keys.end(), extra_keys.begin(), extra_keys.end());
  v.words.insert(v.words.end(), extra_words.begin(), extra_words.end());
  return v;
}

XmlRpc::XmlRpcValue BuildParameters(FuzzedDataProvider& in, const ParameterVocabulary& v) {
  static XmlRpcValue tree;
  last_tree = &tree;
  switch (in.ConsumeIntegralInRange(0, 15)) {
    case 0:
      tree = EmptyStruct();  // nothing set under the namespace
      break;
    case 1:
      tree = XmlRpcValue();  // no namespace at all
      break;
    case 2:
      tree = Value(in, v, 0);  // the namespace is a value, not a section
      break;
    default:
      tree = v.config;
  }
  for (int edit = 0; edit < 48 && in.remaining_bytes() > 0; ++edit) {
    const std::vector<std::string> path = Path(in, v);
    switch (in.ConsumeIntegralInRange(0, 5)) {
      case 0:
        Erase(tree, path);
        break;
      case 1:
      case 2: {
        XmlRpcValue* old = At(tree, path, false);
        const XmlRpcValue nudged = Nudged(in, old ? *old : XmlRpcValue());
        *At(tree, path, true) = nudged;
        break;
      }
      default: {
        const XmlRpcValue value = Value(in, v, 0);
        *At(tree, path, true) = value;
      }
    }
  }
  return tree;
}

std::string ToYaml(const XmlRpc::XmlRpcValue& value) {
  std::ostringstream out;
  Print(value, out, 0);
  return out.str();
}

void Expect(bool ok, const std::string& what) {
  if (!ok) Finding(what);
}

void ExpectFinite(const std::string& name, double value) {
  if (!std::isfinite(value)) Finding(name + " is " + Text(value) + ", not finite");
}

void ExpectIn(const std::string& name, double value, const std::string& range) {
  const size_t comma = range.find(',');
  if (range.size() < 5 || comma == std::string::npos || (range[0] != '(' && range[0] != '[') ||
      (range.back() != ')' && range.back() != ']')) {
    Finding("bad range '" + range + "' in the check of " + name);
  }
  const double lo = Bound(range.substr(1, comma - 1));
  const double hi = Bound(range.substr(comma + 1, range.size() - comma - 2));
  const bool above = range[0] == '(' ? value > lo : value >= lo;
  const bool below = range.back() == ')' ? value < hi : value <= hi;
  if (!std::isfinite(value) || !above || !below) {
    Finding(name + " = " + Text(value) + " was accepted, outside its documented range " + range);
  }
}

void ExpectRosDuration(const std::string& name, double seconds) {
  // ros::Duration's fromSec casts floor(seconds) to int64 (undefined beyond it) and throws
  // beyond int32: check first, then make one.
  if (!(std::isfinite(seconds) && std::fabs(seconds) < 2147483647.0)) {
    Finding(name + " = " + Text(seconds) + " s was accepted, and ros::Duration cannot hold it");
  }
  try {
    const ros::Duration d(seconds);
    (void)d;
  } catch (const std::exception& e) {
    Finding(name + " = " + Text(seconds) + " s: ros::Duration throws " + e.what());
  }
}

}  // namespace spott_fuzz
