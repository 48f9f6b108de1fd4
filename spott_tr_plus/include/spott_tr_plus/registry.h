// Binds the names of a TR+ program's conditions and primitive actions to C++ functions
// (SPOTT III.C: "conditions are ... typically computed as separate processes"; actions drive
// actuators or update the map database).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "spott_tr_plus/value.h"

namespace spott_tr_plus {

/// Identifies one asynchronous condition computation or one running primitive action; the
/// binding hands it back to Interpreter::CompleteCondition / CompleteAction.
using Ticket = uint64_t;

/// What a condition process is asked to compute.
struct ConditionCall {
  const std::string& name;
  const std::vector<Value>& inputs;  ///< The declared inputs, in order.
  double now;                        ///< Caller's clock (s).
  Ticket ticket;                     ///< Asynchronous conditions only.
};

/// A primitive action being started.
struct ActionCall {
  const std::string& name;
  const std::vector<Value>& args;
  double now;
  Ticket ticket;  ///< Hand back to Interpreter::CompleteAction when the action finishes.
};

class Registry {
 public:
  /// Computes at once; writes the declared outputs (pre-sized) and returns the truth value.
  using SyncConditionFn = std::function<bool(const ConditionCall&, std::vector<Value>& outputs)>;
  /// Starts a computation that reports later through Interpreter::CompleteCondition.
  using AsyncConditionFn = std::function<void(const ConditionCall&)>;
  using ActionStart = std::function<void(const ActionCall&)>;
  using ActionStop = std::function<void(Ticket)>;
  using InstantFn = std::function<void(const std::vector<Value>& args, double now)>;

  enum class ConditionKind { kSync, kAsync, kExternal };
  struct ConditionBinding {
    ConditionKind kind = ConditionKind::kSync;
    SyncConditionFn sync;
    AsyncConditionFn async;
  };
  struct ActionBinding {
    ActionStart start;  ///< Empty for instant actions.
    ActionStop stop;    ///< May be empty: nothing to stop.
    InstantFn instant;  ///< Runs and completes at once.
  };

  /// A condition computed inline, on every scan (frequency 0) or at its declared frequency.
  Registry& Condition(const std::string& name, SyncConditionFn fn);
  /// A condition computed elsewhere (a thread, another process) at its declared frequency.
  Registry& AsyncCondition(const std::string& name, AsyncConditionFn fn);
  /// A condition whose value is pushed with Interpreter::SetCondition (topics, sensors).
  Registry& ExternalCondition(const std::string& name);
  /// An action that runs until it calls Interpreter::CompleteAction (or is stopped).
  Registry& Action(const std::string& name, ActionStart start, ActionStop stop = nullptr);
  /// An action that completes as soon as it is started.
  Registry& InstantAction(const std::string& name, InstantFn fn);

  const ConditionBinding* FindCondition(const std::string& name) const;
  const ActionBinding* FindAction(const std::string& name) const;

 private:
  std::unordered_map<std::string, ConditionBinding> conditions_;
  std::unordered_map<std::string, ActionBinding> actions_;
};

}  // namespace spott_tr_plus
