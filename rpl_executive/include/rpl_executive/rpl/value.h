// Values of RPL plans (Beetz et al. section 3: "RPL programs look very much like LISP programs"):
// NIL, T, numbers, strings, symbols (keywords such as :FAST are symbols) and lists. As in Lisp,
// NIL is the empty list and the only false value; every other value is true.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rpl_executive {
namespace rpl {

class Value {
 public:
  enum class Type { kNil, kTrue, kNumber, kString, kSymbol, kList };

  Value() = default;  // NIL
  static Value Nil() { return Value(); }
  static Value True();
  static Value Boolean(bool b) { return b ? True() : Nil(); }
  static Value Number(double x);
  static Value String(std::string s);
  /// A symbol, upper case as the reader folds it ("WHEELS", ":FAST"). "NIL" and "T" give NIL
  /// and T.
  static Value Symbol(std::string name);
  /// A list; the empty list is NIL.
  static Value List(std::vector<Value> items);
  /// A point (x y) in the map frame (m), as NAVIGATION takes its destination.
  static Value Point(double x_m, double y_m);

  Type type() const { return type_; }
  bool IsNil() const { return type_ == Type::kNil; }
  /// Lisp truth: everything but NIL.
  bool Truthy() const { return type_ != Type::kNil; }
  bool IsNumber() const { return type_ == Type::kNumber; }
  bool IsString() const { return type_ == Type::kString; }
  bool IsSymbol() const { return type_ == Type::kSymbol; }
  bool IsList() const { return type_ == Type::kList; }

  /// The number; 0 for other types (check IsNumber first).
  double number() const { return number_; }
  /// The text of a string or the name of a symbol; "" otherwise.
  const std::string& text() const;
  /// The items of a list; empty for other types (NIL included).
  const std::vector<Value>& items() const;

  /// Structural equality (Lisp EQUAL): numbers compare exactly.
  bool operator==(const Value& other) const;
  bool operator!=(const Value& other) const { return !(*this == other); }

  /// Printed as the reader reads it back: NIL, T, 0.8, "text", :FAST, (19.6 6).
  std::string ToString() const;
  /// "number", "string", ...: for error messages.
  static const char* TypeName(Type type);

 private:
  Type type_ = Type::kNil;
  double number_ = 0.0;
  std::shared_ptr<const std::string> text_;         // kString, kSymbol
  std::shared_ptr<const std::vector<Value>> list_;  // kList
};

}  // namespace rpl
}  // namespace rpl_executive
