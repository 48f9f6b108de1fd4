#include "rpl_executive/noreils_chatila/value.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rpl_executive::noreils_chatila {

namespace {

bool IsNilName(const std::string& name) {
  if (name.size() != 3) return false;
  return std::toupper(static_cast<unsigned char>(name[0])) == 'N' &&
         std::toupper(static_cast<unsigned char>(name[1])) == 'I' &&
         std::toupper(static_cast<unsigned char>(name[2])) == 'L';
}

}  // namespace

Value Value::Symbol(std::string name) {
  Value v;
  if (IsNilName(name)) return v;
  v.kind_ = Kind::kSymbol;
  v.symbol_ = std::move(name);
  return v;
}

Value Value::Number(double number) {
  Value v;
  v.kind_ = Kind::kNumber;
  v.number_ = number;
  return v;
}

Value Value::List(std::vector<Value> items) {
  Value v;
  if (items.empty()) return v;
  v.kind_ = Kind::kList;
  v.list_ = std::move(items);
  return v;
}

const std::string& Value::symbol() const {
  if (kind_ != Kind::kSymbol) throw std::logic_error("Value::symbol() on a non-symbol");
  return symbol_;
}

double Value::number() const {
  if (kind_ != Kind::kNumber) throw std::logic_error("Value::number() on a non-number");
  return number_;
}

const std::vector<Value>& Value::list() const {
  if (kind_ != Kind::kList) throw std::logic_error("Value::list() on a non-list");
  return list_;
}

bool Value::operator==(const Value& other) const {
  if (kind_ != other.kind_) return false;
  switch (kind_) {
    case Kind::kNil:
      return true;
    case Kind::kSymbol:
      return symbol_ == other.symbol_;
    case Kind::kNumber:
      return number_ == other.number_;
    case Kind::kList:
      return list_ == other.list_;
  }
  return false;
}

std::string NumberText(double number) {
  if (std::isfinite(number) && number == std::floor(number) && std::fabs(number) < 1e15) {
    return std::to_string(static_cast<long long>(number));
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", number);
  return buffer;
}

std::string Value::ToText() const {
  switch (kind_) {
    case Kind::kNil:
      return "NIL";
    case Kind::kSymbol:
      return symbol_;
    case Kind::kNumber:
      return NumberText(number_);
    case Kind::kList: {
      std::string out = "(";
      for (size_t i = 0; i < list_.size(); ++i) {
        if (i > 0) out += ' ';
        out += list_[i].ToText();
      }
      return out + ")";
    }
  }
  return "NIL";
}

}  // namespace rpl_executive::noreils_chatila
