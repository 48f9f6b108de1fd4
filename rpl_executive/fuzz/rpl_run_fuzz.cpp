// Fuzzes the RPL runtime: every plan that checks is run on scripted modules through a fixed
// schedule of fluent changes and module reports, then aborted. Besides crashes and sanitizer
// reports it checks that a plan that ended leaves nothing behind: no live task, no active module,
// no valve held. An input whose first byte is odd is not plan text but the choices of a plan
// generator (every construct, nested), so that most inputs are plans that check and run.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_robot.h"

namespace {
using namespace rpl_executive::rpl;

// Builds a plan from bytes: each byte chooses a construct; the plan always checks.
class Generator {
 public:
  Generator(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  std::string Plan() {
    std::string out =
        "(DEF-PULSE P1 (= NR-OF-NAV-GOALS* 0))\n(DEF-PULSE P2)\n"
        "(DEF-FLUENT L (<= POS-CERTAINTY* 0.5))\n(DEF-FLUENT N 0)\n";
    for (int i = 0; i < 3; ++i) {
      out += "(DEFUN F" + std::to_string(i) + " (A) " + Statement(3) + ")\n";
    }
    out += Statement(6) + "\n" + Statement(4) + "\n";
    return out;
  }

 private:
  int Next(int n) { return pos_ < size_ ? data_[pos_++] % n : 0; }
  std::string Condition(int depth) {
    switch (Next(depth > 0 ? 11 : 9)) {
      case 0:
        return "(<= POS-CERTAINTY* 0.5)";
      case 1:
        return "(= NR-OF-NAV-GOALS* 0)";
      case 2:
        return "P1";
      case 3:
        return "P2";
      case 4:
        return "L";
      case 5:
        return "(> N " + std::to_string(Next(4)) + ")";
      case 6:
        return "T";
      case 7:
        return "NIL";
      case 8:
        return "(> X* A)";
      case 9:
        return "(AND " + Condition(depth - 1) + " " + Condition(depth - 1) + ")";
      default:
        return "(NOT " + Condition(depth - 1) + ")";
    }
  }
  std::string Module() {
    switch (Next(4)) {
      case 0:
        return "NAVIGATION '(1 2)";
      case 1:
        return "ACTIVE-LOCALIZATION";
      case 2:
        return "ARM";
      default:
        return "POSITION-TRACKING";
    }
  }
  std::string ModuleName() {
    const char* names[] = {"NAVIGATION", "ACTIVE-LOCALIZATION", "ARM", "POSITION-TRACKING"};
    return names[Next(4)];
  }
  std::string Statement(int depth) {
    if (depth <= 0 || pos_ >= size_) {
      switch (Next(4)) {
        case 0:
          return "(WAIT-TIME " + std::to_string(Next(3)) + ")";
        case 1:
          return "(TRACE A)";
        case 2:
          return "(SETF N (+ N 1))";
        default:
          return "(WAIT-FOR " + Condition(1) + ")";
      }
    }
    const int d = depth - 1;
    switch (Next(24)) {
      case 0:
        return "(SEQ " + Statement(d) + " " + Statement(d) + ")";
      case 1:
        return "(PAR " + Statement(d) + " " + Statement(d) + ")";
      case 2:
        return "(TRY-ALL " + Statement(d) + " " + Statement(d) + ")";
      case 3:
        return "(TRY-IN-ORDER " + Statement(d) + " " + Statement(d) + ")";
      case 4:
        return "(IF " + Condition(1) + " " + Statement(d) + " " + Statement(d) + ")";
      case 5:
        return "(LOOP " + Statement(d) + " UNTIL " + Condition(1) + ")";
      case 6:
        return "(LOOP UNTIL " + Condition(1) + " " + Statement(d) + ")";
      case 7:
        return "(WHENEVER " + Condition(2) + " " + Statement(d) + ")";
      case 8:
        return "(WAIT-FOR " + Condition(2) + ")";
      case 9:
        return "(WAIT-TIME " + std::to_string(Next(4)) + ")";
      case 10:
        return "(WITH-POLICY " + Statement(d) + " " + Statement(d) + ")";
      case 11:
        return std::string("(WITH-VALVE ") + (Next(2) ? "WHEELS " : "GRIPPER ") + Statement(d) +
               ")";
      case 12:
        return "(EVAP-PROTECT " + Statement(d) + " " + Statement(d) + ")";
      case 13:
        return "(PROCESS P " + Statement(d) + ")";
      case 14:
        return "(LET ((A (+ A 1))) " + Statement(d) + ")";
      case 15:
        return "(EXECUTE " + Module() + ")";
      case 16:
        return "(ACTIVATE " + Module() + ")";
      case 17:
        return "(DEACTIVATE " + ModuleName() + ")";
      case 18:
        return "(FAIL \"f\")";
      case 19:
        return std::string("(PULSE ") + (Next(2) ? "P1" : "P2") + ")";
      case 20:
        return "(SETF N (+ N 1))";
      case 21: {
        const char* classes[] = {"FAILURE",      "MODULE-FAILURE", "INTERRUPTED",
                                 "PLAN-FAILURE", "RUNTIME-ERROR",  "ALL-FAILED"};
        return "(WITH-FAILURE-HANDLING " + Statement(d) + " (" + classes[Next(6)] + " (W) " +
               Statement(d) + "))";
      }
      case 22:
        return "(F" + std::to_string(Next(3)) + " (+ A 1))";
      default:
        return "(VERIFY-CONDITION " + Condition(1) + ")";
    }
  }
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 1;
};

class Module : public BehaviourModule {
 public:
  explicit Module(ModuleSpec spec) : spec_(std::move(spec)) {}
  ModuleSpec Spec() const override { return spec_; }
  void Activate(ActivationId id, const std::vector<Value>&, double) override {
    if (active) std::abort();  // the runtime deactivates the old activation first
    active = id;
  }
  void Deactivate(ActivationId id, double) override {
    if (active == id) {
      active = 0;
    } else if (active != 0) {
      std::abort();  // another activation of the module is the current one
    }
  }
  ActivationId active = 0;

 private:
  ModuleSpec spec_;
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  const bool generated = size > 0 && (data[0] & 1);
  const std::string text = generated ? "(DEFVAR A 0)\n" + Generator(data, size).Plan()
                                     : std::string(reinterpret_cast<const char*>(data), size);
  if (std::getenv("RPL_FUZZ_PRINT")) std::fprintf(stderr, "%s\n", text.c_str());
  ExecutiveParameters p;
  p.max_instructions_per_step = 2000;
  p.max_call_depth = 40;
  p.event_log_capacity = 16;
  p.max_live_tasks = 20000;
  Executive e(p);
  for (const auto& f : office::Fluents()) e.DeclareFluent(f);
  std::vector<std::shared_ptr<Module>> modules = {
      std::make_shared<Module>(office::NavigationSpec()),
      std::make_shared<Module>(office::PositionTrackingSpec()),
      std::make_shared<Module>(office::ActiveLocalizationSpec()),
      std::make_shared<Module>(ModuleSpec{"ARM", 0, 1, {"GRIPPER"}, ""})};
  for (auto& m : modules) e.AddModule(m);
  e.AddFunction({"TRACE", 1, -1, ""}, [](const std::vector<Value>&) {
    return HostResult{Value::True(), ""};
  });
  if (HasErrors(e.Load(text, "fuzz.rpl"))) {
    if (generated) std::abort();  // the generator writes only plans that check
    return 0;
  }
  if (!e.Start(0.0).empty()) return 0;
  const char* fluents[] = {office::kPosCertainty, office::kNrOfNavGoals, office::kX,
                           office::kNavigationActive};
  for (int i = 0; i < 40 && e.state() == PlanState::kRunning; ++i) {
    const double t = 0.5 * i;
    e.SetFluent(fluents[i % 4], i % 3 == 0 ? Value() : Value::Number((i * 37) % 11 / 10.0), t);
    for (size_t m = 0; m < modules.size(); ++m) {
      if (modules[m]->active && (i + m) % 5 == 0) {
        if (i % 2) {
          e.ReportSuccess(modules[m]->active, Value::Number(i));
        } else {
          e.ReportFailure(modules[m]->active, "scripted failure");
        }
        modules[m]->active = 0;
      }
    }
    if (i == 30) e.SeizeValve(office::kWheels, "reflex", t);
    if (i == 32) e.ReturnValve(office::kWheels, t);
    e.Step(t);
    if (i % 8 == 0 && e.NumLiveTasks() < 5000) (void)e.TaskTree();
  }
  e.Abort(20.0);
  for (int i = 0; i < 40 && e.state() == PlanState::kRunning; ++i) e.Step(20.0 + i);
  if (e.state() != PlanState::kRunning) {
    if (e.NumLiveTasks() != 0) std::abort();
    for (auto& m : modules) {
      if (m->active) std::abort();
    }
    if (!e.ValveHolder(office::kWheels).empty() || !e.ValveHolder("GRIPPER").empty()) std::abort();
  }
  return 0;
}
