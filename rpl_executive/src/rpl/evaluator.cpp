// Evaluation of pure forms (expressions that never block): constants, variables, fluents,
// builtins, host functions and pure procedures. Conditions of WAIT-FOR and WHENEVER are such
// forms; the fluent network re-evaluates them when an input fluent changes.
#include <cmath>
#include <iterator>

#include "runtime.h"

namespace rpl_executive {
namespace rpl {
namespace internal {

namespace {

EvalResult Ok(Value v) { return {std::move(v), "", nullptr}; }
EvalResult Error(const Form* where, std::string message) {
  return {Value(), std::move(message), where};
}

std::string Head(const Form* f) {
  if (f->datum && f->datum->IsList() && !f->datum->items.empty()) {
    return PrintDatum(f->datum->items[0]);
  }
  return "?";
}

std::string NotA(const Form* f, size_t i, const Value& v, const char* wanted) {
  return "(" + Head(f) + " ...): argument " + std::to_string(i + 1) + " is " + v.ToString() +
         ", not " + wanted;
}

// The x, y (m) of a point (x y ...).
bool PointOf(const Value& v, double* x, double* y) {
  if (!v.IsList() || v.items().size() < 2 || !v.items()[0].IsNumber() || !v.items()[1].IsNumber()) {
    return false;
  }
  *x = v.items()[0].number();
  *y = v.items()[1].number();
  return true;
}

}  // namespace

EvalResult Runtime::Eval(const Form* f, Frame* frame, int depth) {
  if (depth > params_.max_call_depth * 16) {
    return Error(f, "expression nested deeper than max_call_depth * 16 = " +
                        std::to_string(params_.max_call_depth * 16) + " (runaway recursion?)");
  }
  switch (f->kind) {
    case FormKind::kConstant:
      return Ok(f->constant);
    case FormKind::kLocal:
      if (!frame || f->index >= static_cast<int>(frame->slots.size())) {
        return Error(f, "internal: variable outside its frame");
      }
      return Ok(frame->slots[f->index]);
    case FormKind::kGlobal:
      return Ok(globals_[f->index]);
    case FormKind::kFluent:
      return Ok(nodes_[f->index]->value);
    case FormKind::kIf: {
      EvalResult c = Eval(f->args[0], frame, depth + 1);
      if (!c.ok()) return c;
      return Eval(f->args[c.value.Truthy() ? 1 : 2], frame, depth + 1);
    }
    case FormKind::kAnd: {
      Value last = Value::True();
      for (const Form* a : f->args) {
        EvalResult r = Eval(a, frame, depth + 1);
        if (!r.ok() || !r.value.Truthy()) return r;
        last = std::move(r.value);
      }
      return Ok(last);
    }
    case FormKind::kOr: {
      for (const Form* a : f->args) {
        EvalResult r = Eval(a, frame, depth + 1);
        if (!r.ok() || r.value.Truthy()) return r;
      }
      return Ok(Value());
    }
    case FormKind::kBuiltin:
      if (f->args.size() <= 4) {  // the usual case: no allocation
        Value args[4];
        for (size_t i = 0; i < f->args.size(); ++i) {
          EvalResult r = Eval(f->args[i], frame, depth + 1);
          if (!r.ok()) return r;
          args[i] = std::move(r.value);
        }
        return ApplyBuiltin(f, args, f->args.size());
      }
      [[fallthrough]];
    case FormKind::kHostCall:
    case FormKind::kCall: {
      std::vector<Value> args;
      args.reserve(f->args.size());
      for (const Form* a : f->args) {
        EvalResult r = Eval(a, frame, depth + 1);
        if (!r.ok()) return r;
        args.push_back(std::move(r.value));
      }
      if (f->kind == FormKind::kBuiltin) return ApplyBuiltin(f, args.data(), args.size());
      if (f->kind == FormKind::kHostCall) return CallHost(f, args);
      const Procedure& p = plan_->procedures[f->index];
      Frame callee(p.frame_size);
      for (int i = 0; i < p.num_params; ++i) callee.slots[i] = std::move(args[i]);
      return Eval(p.body, &callee, depth + 16);
    }
    default:
      return Error(f, "internal: " + Plan::Text(*f) + " is not an expression");
  }
}

EvalResult Runtime::CallHost(const Form* f, const std::vector<Value>& args) {
  ++in_callback_;
  HostResult r = functions_[f->index](args);
  --in_callback_;
  if (!r.ok()) return Error(f, vocabulary_.functions[f->index].name + ": " + r.error);
  return Ok(std::move(r.value));
}

EvalResult Runtime::ApplyBuiltin(const Form* f, Value* args, size_t n) {
  const auto op = static_cast<Builtin>(f->index);
  auto numbers = [&](size_t from) -> std::string {
    for (size_t i = from; i < n; ++i) {
      if (!args[i].IsNumber()) return NotA(f, i, args[i], "a number");
    }
    return "";
  };
  switch (op) {
    case Builtin::kAdd:
    case Builtin::kMul:
    case Builtin::kSub:
    case Builtin::kDiv: {
      const std::string e = numbers(0);
      if (!e.empty()) return Error(f, e);
      if (op == Builtin::kAdd || op == Builtin::kMul) {
        double acc = op == Builtin::kAdd ? 0.0 : 1.0;
        for (size_t i = 0; i < n; ++i) {
          acc = op == Builtin::kAdd ? acc + args[i].number() : acc * args[i].number();
        }
        return Ok(Value::Number(acc));
      }
      if (n == 1) {
        const double x = args[0].number();
        if (op == Builtin::kSub) return Ok(Value::Number(-x));
        if (x == 0.0) return Error(f, "(/ 0): division by zero");
        return Ok(Value::Number(1.0 / x));
      }
      double acc = args[0].number();
      for (size_t i = 1; i < n; ++i) {
        if (op == Builtin::kSub) {
          acc -= args[i].number();
        } else {
          if (args[i].number() == 0.0) return Error(f, "(/ ...): division by zero");
          acc /= args[i].number();
        }
      }
      return Ok(Value::Number(acc));
    }
    case Builtin::kNumEq:
    case Builtin::kNumNe:
    case Builtin::kLt:
    case Builtin::kLe:
    case Builtin::kGt:
    case Builtin::kGe: {
      const std::string e = numbers(0);
      if (!e.empty()) return Error(f, e);
      for (size_t i = 0; i + 1 < n; ++i) {
        const double a = args[i].number(), b = args[i + 1].number();
        bool holds = false;
        switch (op) {
          case Builtin::kNumEq:
            holds = a == b;
            break;
          case Builtin::kNumNe:
            holds = a != b;
            break;
          case Builtin::kLt:
            holds = a < b;
            break;
          case Builtin::kLe:
            holds = a <= b;
            break;
          case Builtin::kGt:
            holds = a > b;
            break;
          default:
            holds = a >= b;
            break;
        }
        if (!holds) return Ok(Value());
      }
      return Ok(Value::True());
    }
    case Builtin::kNot:
      return Ok(Value::Boolean(!args[0].Truthy()));
    case Builtin::kAbs:
    case Builtin::kSqrt: {
      const std::string e = numbers(0);
      if (!e.empty()) return Error(f, e);
      const double x = args[0].number();
      if (op == Builtin::kAbs) return Ok(Value::Number(std::fabs(x)));
      if (x < 0) return Error(f, "(SQRT " + args[0].ToString() + "): negative argument");
      return Ok(Value::Number(std::sqrt(x)));
    }
    case Builtin::kMin:
    case Builtin::kMax: {
      const std::string e = numbers(0);
      if (!e.empty()) return Error(f, e);
      double acc = args[0].number();
      for (size_t i = 0; i < n; ++i) {
        acc = op == Builtin::kMin ? std::fmin(acc, args[i].number())
                                  : std::fmax(acc, args[i].number());
      }
      return Ok(Value::Number(acc));
    }
    case Builtin::kList:
      return Ok(Value::List(
          std::vector<Value>(std::make_move_iterator(args), std::make_move_iterator(args + n))));
    case Builtin::kFirst:
    case Builtin::kSecond:
    case Builtin::kThird:
    case Builtin::kLength: {
      if (!args[0].IsList() && !args[0].IsNil()) return Error(f, NotA(f, 0, args[0], "a list"));
      const auto& items = args[0].items();
      if (op == Builtin::kLength) return Ok(Value::Number(static_cast<double>(items.size())));
      const size_t i = op == Builtin::kFirst ? 0 : op == Builtin::kSecond ? 1 : 2;
      return Ok(i < items.size() ? items[i] : Value());
    }
    case Builtin::kNth: {
      if (!args[0].IsNumber()) return Error(f, NotA(f, 0, args[0], "a number"));
      if (!args[1].IsList() && !args[1].IsNil()) return Error(f, NotA(f, 1, args[1], "a list"));
      const double k = args[0].number();
      const auto& items = args[1].items();
      if (k < 0 || k != std::floor(k)) return Error(f, NotA(f, 0, args[0], "an index (0, 1, ...)"));
      return Ok(k < static_cast<double>(items.size()) ? items[static_cast<size_t>(k)] : Value());
    }
    case Builtin::kDistance: {
      double x0, y0, x1, y1;
      if (!PointOf(args[0], &x0, &y0)) return Error(f, NotA(f, 0, args[0], "a point (X Y)"));
      if (!PointOf(args[1], &x1, &y1)) return Error(f, NotA(f, 1, args[1], "a point (X Y)"));
      return Ok(Value::Number(std::hypot(x1 - x0, y1 - y0)));
    }
    case Builtin::kConcat: {
      std::string out;
      for (size_t i = 0; i < n; ++i)
        out += args[i].IsString() ? args[i].text() : args[i].ToString();
      return Ok(Value::String(std::move(out)));
    }
    case Builtin::kEqual:
      return Ok(Value::Boolean(args[0] == args[1]));
  }
  return Error(f, "internal: unknown builtin");
}

}  // namespace internal
}  // namespace rpl
}  // namespace rpl_executive
