// Values of the Noreils-Chatila mission language (section 5): NIL, symbols (T, ON, ZONE109),
// numbers and lists. Numbers carry the mission's units: lengths in cm, angles in tenths of a
// degree, speeds in cm/s (README "Units of the mission language").
#pragma once

#include <string>
#include <vector>

namespace rpl_executive::noreils_chatila {

class Value {
 public:
  enum class Kind { kNil, kSymbol, kNumber, kList };

  Value() = default;  ///< NIL.
  static Value Nil() { return Value(); }
  /// A symbol; "NIL" (any case) is NIL itself.
  static Value Symbol(std::string name);
  static Value Number(double number);
  /// A list; the empty list is NIL, as in Lisp.
  static Value List(std::vector<Value> items);
  static Value True() { return Symbol("T"); }

  Kind kind() const { return kind_; }
  bool IsNil() const { return kind_ == Kind::kNil; }
  /// Everything but NIL is true (the paper's (IF (LOA) ...) and (WHILE (robot-in-zone) ...)).
  bool IsTrue() const { return !IsNil(); }
  bool IsSymbol() const { return kind_ == Kind::kSymbol; }
  bool IsNumber() const { return kind_ == Kind::kNumber; }
  bool IsList() const { return kind_ == Kind::kList; }

  /// Preconditions: the value has that kind (a programming error otherwise: std::logic_error).
  const std::string& symbol() const;
  double number() const;
  const std::vector<Value>& list() const;

  bool operator==(const Value& other) const;
  bool operator!=(const Value& other) const { return !(*this == other); }

  /// The value as mission text: NIL, T, 150, 0.5, ((150 500) (150 700)).
  std::string ToText() const;

 private:
  Kind kind_ = Kind::kNil;
  std::string symbol_;
  double number_ = 0.0;
  std::vector<Value> list_;
};

/// Formats a number as the mission text does: integers without a point, others with up to 10
/// significant digits.
std::string NumberText(double number);

}  // namespace rpl_executive::noreils_chatila
