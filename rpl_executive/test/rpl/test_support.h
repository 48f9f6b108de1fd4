// In-process behaviour modules and helpers for the RPL tests: modules that record what the
// runtime asks of them and report when the test says so, and a TRACE function that records the
// order in which threads of control run.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_robot.h"

namespace rpl_executive {
namespace rpl {
namespace testing {

/// A module that does nothing by itself: it records activations and deactivations; the test
/// reports success or failure for it.
class ScriptedModule : public BehaviourModule {
 public:
  struct Call {
    ActivationId id;
    std::vector<Value> args;
    double time_s;
  };
  ScriptedModule(Executive* executive, ModuleSpec spec) : executive_(executive), spec_(spec) {}

  ModuleSpec Spec() const override { return spec_; }
  void Activate(ActivationId id, const std::vector<Value>& args, double now_s) override {
    activations.push_back({id, args, now_s});
    active = id;
    if (on_activate) on_activate(id, args, now_s);
  }
  void Deactivate(ActivationId id, double now_s) override {
    deactivations.push_back({id, {}, now_s});
    if (active == id) active = 0;
    if (on_deactivate) on_deactivate(id, now_s);
  }

  bool IsActive() const { return active != 0; }
  void Succeed(const Value& v = Value::True()) {
    ASSERT_NE(active, 0u) << spec_.name << " is not active";
    executive_->ReportSuccess(active, v);
    active = 0;
  }
  void FailWith(const std::string& cause) {
    ASSERT_NE(active, 0u) << spec_.name << " is not active";
    executive_->ReportFailure(active, cause);
    active = 0;
  }

  std::vector<Call> activations;
  std::vector<Call> deactivations;
  ActivationId active = 0;
  std::function<void(ActivationId, const std::vector<Value>&, double)> on_activate;
  std::function<void(ActivationId, double)> on_deactivate;

 private:
  Executive* executive_;
  ModuleSpec spec_;
};

/// An executive with the office robot's fluents, scripted NAVIGATION, POSITION-TRACKING and
/// ACTIVE-LOCALIZATION modules, a module ARM without valves, a valve GRIPPER, plan fluents to
/// play with (F*, G* numbers; FLAG* T/NIL) and (TRACE x ...) which appends its arguments to
/// `trace`.
struct Harness {
  explicit Harness(ExecutiveParameters p = ExecutiveParameters()) : executive(p) {
    for (const auto& f : office::Fluents()) executive.DeclareFluent(f);
    executive.DeclareFluent({"F*", Value::Number(0), "a number"});
    executive.DeclareFluent({"G*", Value::Number(0), "a number"});
    executive.DeclareFluent({"FLAG*", Value(), "T or NIL"});
    navigation = std::make_shared<ScriptedModule>(&executive, office::NavigationSpec());
    tracking = std::make_shared<ScriptedModule>(&executive, office::PositionTrackingSpec());
    localization = std::make_shared<ScriptedModule>(&executive, office::ActiveLocalizationSpec());
    arm = std::make_shared<ScriptedModule>(&executive, ModuleSpec{"ARM", 0, 1, {"GRIPPER"}, ""});
    executive.AddModule(navigation);
    executive.AddModule(tracking);
    executive.AddModule(localization);
    executive.AddModule(arm);
    executive.AddFunction(
        {"TRACE", 1, -1, "records its arguments"}, [this](const std::vector<Value>& args) {
          std::string s;
          for (const auto& a : args) {
            s += (s.empty() ? "" : " ") + (a.IsString() ? a.text() : a.ToString());
          }
          trace.push_back(s);
          return HostResult{Value::True(), ""};
        });
  }

  /// Loads and starts `text`; fails the test on any diagnostic error.
  void Run(const std::string& text, double now_s = 0.0) {
    const auto diagnostics = executive.Load(text, "test.rpl");
    ASSERT_FALSE(HasErrors(diagnostics)) << FormatDiagnostics(diagnostics);
    ASSERT_EQ(executive.Start(now_s), "");
  }
  StepResult Step(double now_s) {
    now = now_s;
    return executive.Step(now_s);
  }
  void Set(const std::string& fluent, const Value& v) { executive.SetFluent(fluent, v, now); }
  std::string Trace() const {
    std::string s;
    for (const auto& t : trace) s += (s.empty() ? "" : ", ") + t;
    return s;
  }
  /// Events of one kind, as "subject: detail".
  std::vector<std::string> Events(Event::Kind kind) const {
    std::vector<std::string> out;
    for (const auto& e : executive.events()) {
      if (e.kind == kind) out.push_back(e.subject + (e.detail.empty() ? "" : ": " + e.detail));
    }
    return out;
  }

  Executive executive;
  std::shared_ptr<ScriptedModule> navigation, tracking, localization, arm;
  std::vector<std::string> trace;
  double now = 0.0;
};

}  // namespace testing
}  // namespace rpl
}  // namespace rpl_executive
