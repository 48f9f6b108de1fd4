#include "rpl_executive/rpl/value.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "spott_text/lexemes.h"

namespace rpl_executive {
namespace rpl {

namespace {
const std::string& EmptyString() {
  static const std::string* empty = new std::string();
  return *empty;
}
const std::vector<Value>& EmptyList() {
  static const std::vector<Value>* empty = new std::vector<Value>();
  return *empty;
}

std::string FormatNumber(double x) {
  if (std::isnan(x)) return "NAN";
  if (std::isinf(x)) return x > 0 ? "INF" : "-INF";
  if (x == std::floor(x) && std::fabs(x) < 1e15) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.0f", x);
    return buffer;
  }
  // The shortest of %.15g and %.17g that reads back to the same double.
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.15g", x);
  if (std::strtod(buffer, nullptr) != x) std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace

Value Value::True() {
  Value v;
  v.type_ = Type::kTrue;
  return v;
}

Value Value::Number(double x) {
  Value v;
  v.type_ = Type::kNumber;
  v.number_ = x;
  return v;
}

Value Value::String(std::string s) {
  Value v;
  v.type_ = Type::kString;
  v.text_ = std::make_shared<const std::string>(std::move(s));
  return v;
}

Value Value::Symbol(std::string name) {
  if (name == "NIL") return Nil();
  if (name == "T") return True();
  Value v;
  v.type_ = Type::kSymbol;
  v.text_ = std::make_shared<const std::string>(std::move(name));
  return v;
}

Value Value::List(std::vector<Value> items) {
  if (items.empty()) return Nil();
  Value v;
  v.type_ = Type::kList;
  v.list_ = std::make_shared<const std::vector<Value>>(std::move(items));
  return v;
}

Value Value::Point(double x_m, double y_m) { return List({Number(x_m), Number(y_m)}); }

const std::string& Value::text() const { return text_ ? *text_ : EmptyString(); }

const std::vector<Value>& Value::items() const { return list_ ? *list_ : EmptyList(); }

bool Value::operator==(const Value& other) const {
  if (type_ != other.type_) return false;
  switch (type_) {
    case Type::kNil:
    case Type::kTrue:
      return true;
    case Type::kNumber:
      return number_ == other.number_;
    case Type::kString:
    case Type::kSymbol:
      return text() == other.text();
    case Type::kList:
      return list_ == other.list_ || items() == other.items();
  }
  return false;
}

std::string Value::ToString() const {
  switch (type_) {
    case Type::kNil:
      return "NIL";
    case Type::kTrue:
      return "T";
    case Type::kNumber:
      return FormatNumber(number_);
    case Type::kString:
      return spott_text::QuoteString(text());
    case Type::kSymbol:
      return text();
    case Type::kList: {
      std::string out = "(";
      for (size_t i = 0; i < items().size(); ++i) {
        if (i) out += ' ';
        out += items()[i].ToString();
      }
      return out + ")";
    }
  }
  return "NIL";
}

const char* Value::TypeName(Type type) {
  switch (type) {
    case Type::kNil:
      return "NIL";
    case Type::kTrue:
      return "T";
    case Type::kNumber:
      return "a number";
    case Type::kString:
      return "a string";
    case Type::kSymbol:
      return "a symbol";
    case Type::kList:
      return "a list";
  }
  return "?";
}

}  // namespace rpl
}  // namespace rpl_executive
