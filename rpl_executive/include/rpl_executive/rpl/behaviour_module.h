// Behaviour modules: "a uniform interface between RPL programs and the continuous control
// processes, such as collision avoidance and localization, run by other modules" (Beetz et al.
// section 3). The RPL runtime activates and deactivates them; they signal success or failure
// asynchronously (Executive::ReportSuccess / ReportFailure) and keep the global fluents up to date
// (Executive::SetFluent).
#pragma once

#include <cstdint>
#include <vector>

#include "rpl_executive/rpl/value.h"
#include "rpl_executive/rpl/vocabulary.h"

namespace rpl_executive {
namespace rpl {

/// Names one activation of a module in its reports. Never 0; never reused by an executive.
using ActivationId = std::uint64_t;

class BehaviourModule {
 public:
  virtual ~BehaviourModule() = default;

  /// Name, arity and valves, as plans see the module. Read once, by Executive::AddModule.
  virtual ModuleSpec Spec() const = 0;

  /// Starts the control process with the plan's arguments. Called inside Executive::Step, with
  /// the valves of Spec() held by the activating thread of control. The module later calls
  /// ReportSuccess(id, value) or ReportFailure(id, cause) once (it may do so inside Activate).
  /// It may set fluents here (e.g. NR-OF-NAV-GOALS*), but must not call Step, Start, Load or
  /// Abort.
  virtual void Activate(ActivationId id, const std::vector<Value>& args, double now_s) = 0;

  /// Stops the control process: the plan deactivated it, the thread of control that activated
  /// it ended or evaporated, or its valve was pre-empted. No report is expected afterwards (one
  /// that comes is ignored). Called inside Step or Abort. A module that keeps a list of target
  /// points deletes them here (section 3.2: "a process has to delete all target points before it
  /// can cause the robot to move somewhere else").
  virtual void Deactivate(ActivationId id, double now_s) = 0;
};

}  // namespace rpl
}  // namespace rpl_executive
