// What a plan may name besides its own definitions: the robot's global fluents, its behaviour
// modules, the valves and host functions (Beetz et al. section 3, Fig. 11: "the behavior
// modules, the fluents, the structured reactive plan, and the RPL runtime system"). The checker
// resolves every name of a plan against a vocabulary before anything runs.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rpl_executive/rpl/value.h"

namespace rpl_executive {
namespace rpl {

/// A behaviour module as plans see it: "a uniform interface between RPL programs and the
/// continuous control processes" (section 3), activated with arguments and deactivated.
struct ModuleSpec {
  std::string name;  // upper case, as plans name it: "NAVIGATION"
  int min_args = 0;  // arguments of (EXECUTE name args...) / (ACTIVATE name args...)
  int max_args = 0;
  /// Valves the module needs while active (section 3.2: "any process ... that asks the robot to
  /// move around requests the valve WHEELS, moves the robot only after it has received WHEELS").
  std::vector<std::string> valves;
  std::string description;
};

/// A global fluent set by the host (the node, or a behaviour module): X*, POS-CERTAINTY*, ...
/// Plans read them; only the host sets them.
struct FluentSpec {
  std::string name;  // upper case
  Value initial;     // value until the host first sets it
  std::string description;
};

/// What a host function returns: a value, or an error (a non-empty message) that fails the
/// calling thread of control with the class RUNTIME-ERROR.
struct HostResult {
  Value value;
  std::string error;
  bool ok() const { return error.empty(); }
  static HostResult Error(std::string message) { return {Value(), std::move(message)}; }
};

/// A function of the host that plans call like a builtin, e.g. a named place of the map. It runs
/// at once (it must not block) and must not call back into the executive.
using HostFunction = std::function<HostResult(const std::vector<Value>& args)>;

struct FunctionSpec {
  std::string name;  // upper case
  int min_args = 0;
  int max_args = 0;  // -1: any number
  std::string description;
};

struct Vocabulary {
  std::vector<FluentSpec> fluents;
  std::vector<ModuleSpec> modules;
  std::vector<FunctionSpec> functions;
  std::vector<std::string> valves;

  /// Index of the named entry, or -1.
  int FindFluent(const std::string& name) const;
  int FindModule(const std::string& name) const;
  int FindFunction(const std::string& name) const;
  int FindValve(const std::string& name) const;
};

}  // namespace rpl
}  // namespace rpl_executive
