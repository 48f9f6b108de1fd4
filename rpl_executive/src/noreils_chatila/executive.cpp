#include "rpl_executive/noreils_chatila/executive.h"

#include <algorithm>
#include <deque>
#include <map>
#include <stdexcept>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const ExecutiveParameters& p) {
  std::vector<std::string> v;
  if (!(p.interruption_report_timeout_s > 0.0)) {
    v.push_back("interruption_report_timeout_s: must be above 0");
  }
  return v;
}

const char* MissionStateName(MissionState state) {
  switch (state) {
    case MissionState::kIdle:
      return "idle";
    case MissionState::kRunning:
      return "running";
    case MissionState::kSucceeded:
      return "succeeded";
    case MissionState::kFailed:
      return "failed";
    case MissionState::kAborted:
      return "aborted";
  }
  return "?";
}

std::string Diagnosis::ToString() const {
  std::string out = "cause: " + cause + "\n";
  if (!where.empty()) out += "where: " + where + "\n";
  out += "monitors fired (" + std::to_string(fired.size()) + "):\n";
  for (const MonitorEvent& e : fired) {
    out += "  <n" + std::to_string(e.id) + "> " + e.label + " => " + e.reflex + "\n";
  }
  for (const std::string& h : halted) out += "halted: " + h + "\n";
  for (const std::string& c : cancelled_monitors) out += "cancelled: " + c + "\n";
  for (const std::string& s : static_monitors)
    out += "static, kept through the failure: " + s + "\n";
  return out;
}

namespace {

enum class FrameKind { kORoot, kMission, kCommand };
enum class OrderState { kNone, kRunning, kCompleted, kInterrupted, kFailed };
enum class Wait { kNone, kFrame, kStep, kResource };

struct Frame {
  int id = 0;
  FrameKind kind = FrameKind::kCommand;
  int parent = 0;
  const Mission* mission = nullptr;      // kMission
  const Statement* statement = nullptr;  // kCommand
  int owner = 0;                         // the activity waiting for this frame
  int main_activity = 0;                 // kMission
  std::optional<OperatorCommand> order;  // kCommand: the execution operator
  const OperatorSpec* spec = nullptr;
  OperatorHandle handle = 0;
  OrderState order_state = OrderState::kNone;
  bool stop_requested = false;  // a stop reflex went to the modules while it ran
  bool in_failure = false;      // a plan failure awaits its static monitors' decision
  std::string failure, failure_where;
};

struct Cursor {
  const std::vector<Statement>* body = nullptr;
  size_t index = 0;
  const Statement* loop = nullptr;  // WHILE
};

struct Activity {
  int id = 0;
  int frame = 0;
  int slot = 0;  // the monitor whose control action this is (0: a MAIN)
  bool is_main = false;
  bool alive = true;
  bool running = false;
  std::vector<Cursor> stack;
  Wait wait = Wait::kNone;
  int wait_frame = 0;
};

// A monitor as written, in the frame that set it. Each activation registers a new SM monitor.
struct Slot {
  enum class State { kIdle, kActive, kAwaitingReport, kControlRunning, kDone };
  int id = 0;
  const Monitor* ast = nullptr;
  std::string file;
  int frame = 0;
  bool o_surveillance = false;
  bool terminal = false;
  bool is_static = false;
  std::string label;
  MonitorId sm_id = 0;
  State state = State::kIdle;
  std::vector<OperatorHandle> awaiting;
  double deadline = 0.0;
  int activity = 0;
};

struct Event {
  enum class Kind { kFired, kReport, kEnvCheck, kRun };
  Kind kind = Kind::kRun;
  Firing firing;
  OperatorHandle handle = 0;
  OperatorReply reply;
  int activity = 0;
};

std::string Where(const std::string& file, Location l) { return LocationText(file, l); }

std::string Shorten(std::string s, size_t n = 100) {
  if (s.size() > n) s = s.substr(0, n - 3) + "...";
  return s;
}

}  // namespace

class Executive::Impl : public SurveillanceListener, public RobotModules {
 public:
  Impl(const ExecutiveParameters& parameters, const SurveillanceParameters& surveillance,
       const SonarRing& ring, RobotModules* modules)
      : parameters_(parameters),
        modules_(modules),
        log_(parameters.message_capacity),
        sm_(surveillance, ring, this, &log_, [this] { return ++next_handle_; }) {
    sm_.set_listener(this);
    Frame root;
    root.id = NewId();
    root.kind = FrameKind::kORoot;
    o_root_ = root.id;
    frames_[root.id] = root;
  }

  // --- the SM's reflex path to the modules (Fig. 5, 6-1) --------------------------------------
  OperatorReply Send(OperatorHandle handle, const OperatorCommand& command, double now) override {
    if (std::holds_alternative<StopCommand>(command)) {
      for (auto& [id, f] : frames_) {
        if (f.order_state == OrderState::kRunning) f.stop_requested = true;
      }
    }
    return modules_->Send(handle, command, now);
  }
  void Halt(OperatorHandle handle, double now) override { modules_->Halt(handle, now); }
  void OnMissionStart(double now) override { modules_->OnMissionStart(now); }

  // --- message 6-2 ------------------------------------------------------------------------------
  void OnMonitorFired(const Firing& firing, double /*now*/) override {
    Event e;
    e.kind = Event::Kind::kFired;
    e.firing = firing;
    queue_.push_back(std::move(e));
  }

  // --- API --------------------------------------------------------------------------------------
  struct Scope {
    Impl* impl;
    Scope(Impl* i, double now) : impl(i) {
      if (impl->depth_ == 0) impl->now_ = now;
      ++impl->depth_;
    }
    ~Scope() {
      if (--impl->depth_ == 0) impl->Drain();
    }
  };

  void SetWorldVariable(const std::string& name, Value value) { world_[name] = std::move(value); }
  void SetRobotState(const std::string& name, Value value) {
    robot_state_[name == "motor" ? std::string("motors") : name] = std::move(value);
  }

  std::vector<Diagnostic> SetOSurveillances(const MissionFile& file, double now) {
    Scope scope(this, now);
    CheckOptions options;
    options.world_variables = world_;
    options.sonar_count = static_cast<int>(sm_.ring().mounts.size());
    std::vector<Diagnostic> d = CheckMissionFile(file, options);
    if (HasErrors(d)) return d;
    // Replace the previous O-surveillances.
    for (int id : SlotsOf(o_root_)) RemoveSlot(id, "replaced");
    for (auto& [id, a] : activities_) {
      if (a.frame == o_root_) a.alive = false;
    }
    o_file_ = std::make_shared<MissionFile>(file);
    o_defs_.clear();
    for (const Definition& def : o_file_->definitions) o_defs_[def.name] = def.value;
    for (const Monitor& m : o_file_->o_surveillances) {
      const int slot = NewSlot(&m, o_file_->file, o_root_, true);
      std::string error;
      if (!Arm(slot, SurveillanceManager::Activation::kNextDatum, &error)) {
        Diagnostic e;
        e.file = o_file_->file;
        e.where = m.where;
        e.message = error;
        d.push_back(e);
        RemoveSlot(slot, "not armed");
      }
    }
    return d;
  }

  StartResult StartMission(const MissionFile& file, double now) {
    Scope scope(this, now);
    StartResult r;
    if (state_ == MissionState::kRunning) {
      r.refusal = "mission '" + mission_name_ + "' is running";
      return r;
    }
    if (file.missions.empty()) {
      r.refusal = LocationText(file.file, {}) + ": the file holds no (MISSION ...)";
      return r;
    }
    CheckOptions options;
    options.world_variables = world_;
    options.sonar_count = static_cast<int>(sm_.ring().mounts.size());
    r.errors = CheckMissionFile(file, options);
    if (HasErrors(r.errors)) {
      r.refusal = "the mission has errors:\n" + FormatDiagnostics(r.errors);
      log_.Add(now_, Message::Kind::kMission, "EM", "", 0, "refused: errors in " + file.file);
      return r;
    }
    auto owned = std::make_shared<MissionFile>(file);
    std::map<std::string, Value> vars;
    for (const Definition& d : owned->definitions) vars[d.name] = d.value;
    std::swap(vars_, vars);
    assigned_ = AssignedVariables(*owned);
    const Mission& m = owned->missions[0];
    for (const Test& t : m.pre) {
      if (!EvalTest(t, owned->file)) {
        r.refusal = "PRE: " + t.ToText() + " does not hold" + Explain(t);
        r.refusal_where = t.where;
        log_.Add(
            now_, Message::Kind::kMission, "EM", "", 0,
            "mission " + m.name + " refused at " + Where(owned->file, t.where) + ": " + r.refusal);
        std::swap(vars_, vars);
        return r;
      }
    }
    CleanupMissionTree();
    mission_file_ = owned;
    mission_name_ = m.name;
    state_ = MissionState::kRunning;
    diagnosis_ = Diagnosis();
    fired_.clear();
    log_.Add(now_, Message::Kind::kMission, "EM", "", 0, "mission " + m.name + " started");
    modules_->OnMissionStart(now_);
    root_mission_ = StartMissionFrame(m, 0, 0);
    r.accepted = true;
    return r;
  }

  void Abort(const std::string& reason, double now) {
    Scope scope(this, now);
    if (state_ != MissionState::kRunning) return;
    log_.Add(now_, Message::Kind::kMission, "EM", "", 0,
             "mission " + mission_name_ + " aborted: " + reason);
    KillTree(root_mission_);
    state_ = MissionState::kAborted;
  }

  void OnSonar(const SonarScan& s, double now) {
    Scope scope(this, now);
    sm_.OnSonar(s, now);
  }
  void OnPose(const PoseDatum& p, double now) {
    Scope scope(this, now);
    sm_.OnPose(p, now);
  }
  void OnLaser(const LaserScan& s, double now) {
    Scope scope(this, now);
    sm_.OnLaser(s, now);
  }
  void OnBattery(const BatteryDatum& b, double now) {
    Scope scope(this, now);
    sm_.OnBattery(b, now);
  }

  void OnOperatorReport(OperatorHandle handle, const OperatorReply& reply, double now) {
    Scope scope(this, now);
    Event e;
    e.kind = Event::Kind::kReport;
    e.handle = handle;
    e.reply = reply;
    queue_.push_back(std::move(e));
  }

  void Step(double now) {
    Scope scope(this, now);
    // Terminal monitors whose interruption report did not come in time.
    std::vector<int> late;
    for (auto& [id, slot] : slots_) {
      if (slot.state == Slot::State::kAwaitingReport && slot.deadline <= now_) late.push_back(id);
    }
    for (int id : late) {
      if (S(id) == nullptr) continue;
      Slot& slot = *S(id);
      log_.Add(now_, Message::Kind::kNote, "EM", "", slot.sm_id,
               "no interruption report within " +
                   NumberText(parameters_.interruption_report_timeout_s) +
                   " s: the executive halts the action");
      for (OperatorHandle h : slot.awaiting) {
        auto it = handle_frame_.find(h);
        if (it == handle_frame_.end()) continue;
        Frame* f = F(it->second);
        if (f != nullptr && f->order_state == OrderState::kRunning) {
          HaltOrder(f);
          f->order_state = OrderState::kInterrupted;
        }
      }
      slot.awaiting.clear();
    }
    PumpProceed();
    std::vector<int> ids;
    for (auto& [id, a] : activities_) {
      if (a.alive && (a.wait == Wait::kStep || a.wait == Wait::kResource)) ids.push_back(id);
    }
    for (int id : ids) {
      Activity* a = A(id);
      if (a == nullptr || !a->alive) continue;
      if (a->wait == Wait::kStep) {
        Cursor& c = a->stack.back();
        a->wait = Wait::kNone;
        if (c.loop != nullptr && EvalTest(c.loop->test, FileOf(*a))) {
          c.index = 0;
        } else {
          a->stack.pop_back();
        }
      } else {
        a->wait = Wait::kNone;
      }
      queue_.push_back(RunEvent(id));
    }
  }

  // --- accessors --------------------------------------------------------------------------------
  MissionState state_ = MissionState::kIdle;
  std::string mission_name_;
  Diagnosis diagnosis_;
  std::vector<MonitorEvent> fired_;
  std::vector<MonitorEvent> pending_events_;

  std::optional<Value> Variable(const std::string& name) const {
    const Lookup l = Resolve(name);
    if (l.kind == Lookup::Kind::kValue) return l.value;
    return std::nullopt;
  }
  MessageLog& log() { return log_; }
  const SurveillanceManager& sm() const { return sm_; }

 private:
  friend class Executive;

  // --- lookups ----------------------------------------------------------------------------------
  int NewId() { return ++next_id_; }
  Frame* F(int id) {
    auto it = frames_.find(id);
    return it == frames_.end() ? nullptr : &it->second;
  }
  Activity* A(int id) {
    auto it = activities_.find(id);
    return it == activities_.end() ? nullptr : &it->second;
  }
  Slot* S(int id) {
    auto it = slots_.find(id);
    return it == slots_.end() ? nullptr : &it->second;
  }
  std::vector<int> SlotsOf(int frame) const {
    std::vector<int> out;
    for (const auto& [id, s] : slots_) {
      if (s.frame == frame) out.push_back(id);
    }
    return out;
  }
  std::vector<int> ChildFrames(int frame) const {
    std::vector<int> out;
    for (const auto& [id, f] : frames_) {
      if (f.parent == frame && id != frame) out.push_back(id);
    }
    return out;
  }
  const std::string& FileOf(const Activity& a) {
    static const std::string kNone;
    if (InTree(a.frame, o_root_) && o_file_) return o_file_->file;
    return mission_file_ ? mission_file_->file : kNone;
  }
  bool InTree(int frame, int root) {
    for (Frame* f = F(frame); f != nullptr; f = F(f->parent)) {
      if (f->id == root) return true;
      if (f->parent == 0) break;
    }
    return false;
  }

  Lookup Resolve(const std::string& name) const {
    Lookup l;
    l.kind = Lookup::Kind::kValue;
    auto v = vars_.find(name);
    if (v != vars_.end()) {
      l.value = v->second;
      return l;
    }
    auto o = o_defs_.find(name);
    if (o != o_defs_.end()) {
      l.value = o->second;
      return l;
    }
    auto r = robot_state_.find(name == "motor" ? std::string("motors") : name);
    if (r != robot_state_.end()) {
      l.value = r->second;
      return l;
    }
    auto w = world_.find(name);
    if (w != world_.end()) {
      l.value = w->second;
      return l;
    }
    for (const std::string& b : BuiltinVariables()) {
      if (b == name) return l;  // NIL until set
    }
    if (assigned_.count(name) != 0) return l;
    l.kind = Lookup::Kind::kNotVariable;
    return l;
  }
  Resolver resolver() const {
    return [this](const std::string& name) { return Resolve(name); };
  }

  bool EvalTest(const Test& t, const std::string& file) {
    switch (t.kind) {
      case Test::Kind::kEq: {
        const Decoded<Value> a = ResolveValueExpr(t.lhs, resolver());
        const Decoded<Value> b = ResolveValueExpr(t.rhs, resolver());
        if (!a.ok() || !b.ok()) {
          Note("test " + t.ToText() + " at " + Where(file, t.where) + ": " +
               (a.ok() ? b.error : a.error) + " (false)");
          return false;
        }
        return a.value == b.value;
      }
      case Test::Kind::kNot:
        return !EvalTest(t.children[0], file);
      case Test::Kind::kAnd:
        for (const Test& c : t.children) {
          if (!EvalTest(c, file)) return false;
        }
        return true;
      case Test::Kind::kOr:
        for (const Test& c : t.children) {
          if (EvalTest(c, file)) return true;
        }
        return false;
      case Test::Kind::kVariable: {
        const Lookup l = Resolve(t.variable);
        return l.kind == Lookup::Kind::kValue && l.value.IsTrue();
      }
      case Test::Kind::kSensor: {
        const Decoded<CompiledCondition> c =
            DecodeCondition(t.sensor[0], resolver(), static_cast<int>(sm_.ring().mounts.size()));
        if (!c.ok()) {
          Note("test " + t.ToText() + " at " + Where(file, t.where) + ": " + c.error + " (false)");
          return false;
        }
        const std::optional<bool> v = sm_.EvaluateOnLatest(c.value, now_);
        if (!v) Note("test " + t.ToText() + ": no recent datum (false)");
        return v.value_or(false);
      }
    }
    return false;
  }

  void CollectNames(const Test& t, std::vector<std::string>* names) {
    if (t.kind == Test::Kind::kVariable) names->push_back(t.variable);
    if (t.kind == Test::Kind::kEq) {
      for (const ValueExpr* v : {&t.lhs, &t.rhs}) {
        if (v->kind != ValueExpr::Kind::kLiteral && Resolve(v->name).kind == Lookup::Kind::kValue) {
          names->push_back(v->name);
        }
      }
    }
    for (const Test& c : t.children) CollectNames(c, names);
  }
  std::string Explain(const Test& t) {
    std::vector<std::string> names;
    CollectNames(t, &names);
    std::string out;
    for (const std::string& n : names) {
      out += (out.empty() ? " (" : ", ") + n + " is " + Shorten(Resolve(n).value.ToText(), 60);
    }
    return out.empty() ? out : out + ")";
  }

  void Note(const std::string& text, int monitor = 0) {
    log_.Add(now_, Message::Kind::kNote, "EM", "", monitor, text);
  }

  static Event RunEvent(int activity) {
    Event e;
    e.kind = Event::Kind::kRun;
    e.activity = activity;
    return e;
  }

  // --- the event loop ---------------------------------------------------------------------------
  void Drain() {
    ++depth_;
    while (!queue_.empty()) {
      Event e = std::move(queue_.front());
      queue_.pop_front();
      switch (e.kind) {
        case Event::Kind::kFired:
          HandleFired(e.firing);
          break;
        case Event::Kind::kReport:
          HandleReport(e.handle, e.reply);
          break;
        case Event::Kind::kEnvCheck:
          HandleEnvCheck();
          break;
        case Event::Kind::kRun:
          RunActivity(e.activity);
          break;
      }
    }
    --depth_;
  }

  // --- frames -----------------------------------------------------------------------------------
  int StartMissionFrame(const Mission& m, int parent, int owner) {
    Frame f;
    f.id = NewId();
    f.kind = FrameKind::kMission;
    f.parent = parent;
    f.mission = &m;
    f.owner = owner;
    const int fid = f.id;
    frames_[fid] = f;
    if (parent == 0) root_mission_ = fid;
    const std::string& file = mission_file_->file;
    for (const Statement& s : m.env) {
      const Decoded<Value> v = ResolveValueExpr(s.value, resolver());
      if (v.ok()) {
        vars_[s.target] = v.value;
        Note("ENV: " + s.target + " = " + Shorten(v.value.ToText(), 60));
      }
    }
    for (const Monitor& mon : m.lsurv) {
      const int slot = NewSlot(&mon, file, fid, false);
      std::string error;
      if (!Arm(slot, SurveillanceManager::Activation::kNextDatum, &error)) {
        MissionFail("LSURV: " + error, Where(file, mon.where));
        return fid;
      }
    }
    Activity a;
    a.id = NewId();
    a.frame = fid;
    a.is_main = true;
    a.stack.push_back(Cursor{&m.main, 0, nullptr});
    activities_[a.id] = a;
    frames_[fid].main_activity = a.id;
    queue_.push_back(RunEvent(a.id));
    return fid;
  }

  // The innermost command the MAIN of mission frame `mission` waits on (0 when none).
  int CurrentCommand(int mission) {
    Frame* m = F(mission);
    if (m == nullptr || m->kind != FrameKind::kMission) return 0;
    Activity* main = A(m->main_activity);
    if (main == nullptr || !main->alive || main->wait != Wait::kFrame) return 0;
    Frame* f = F(main->wait_frame);
    if (f == nullptr) return 0;
    return f->kind == FrameKind::kCommand ? f->id : CurrentCommand(f->id);
  }

  // A command frame as a node shows it: "smooth-move 3 points at mission.nc:15:3".
  std::string CommandText(const Frame* f) const {
    if (f == nullptr || f->statement == nullptr || !mission_file_) return "";
    const Statement& s = *f->statement;
    std::string text =
        f->order ? Describe(*f->order) : (s.kind == Statement::Kind::kRun ? "RUN " : "") + s.op;
    return text + " at " + Where(mission_file_->file, s.where);
  }
  // The command the mission's MAIN waits on, for a node's feedback.
  std::string CurrentCommandText() {
    if (state_ != MissionState::kRunning) return "";
    return CommandText(F(CurrentCommand(root_mission_)));
  }

  // The command a monitor acts on: its own command, or for LSURV monitors and O-surveillances
  // the mission's current command.
  int TargetOfSlot(const Slot& slot) {
    Frame* f = F(slot.frame);
    if (f == nullptr) return 0;
    if (f->kind == FrameKind::kCommand) return f->id;
    if (f->kind == FrameKind::kMission) return CurrentCommand(f->id);
    return state_ == MissionState::kRunning ? CurrentCommand(root_mission_) : 0;
  }
  int TargetOf(int activity) {
    Activity* a = A(activity);
    if (a == nullptr || a->slot == 0) return 0;
    Slot* s = S(a->slot);
    return s == nullptr ? 0 : TargetOfSlot(*s);
  }

  // The command frame at the top of `frame`'s chain of commands (a plan failure's scope).
  int TopCommand(int frame) {
    Frame* f = F(frame);
    while (f != nullptr) {
      Frame* p = F(f->parent);
      if (p == nullptr || p->kind != FrameKind::kCommand) return f->id;
      f = p;
    }
    return frame;
  }

  void HaltOrder(Frame* f) {
    if (f->order_state != OrderState::kRunning) return;
    log_.Add(now_, Message::Kind::kHalt, "EM", ModuleName(*f->order), 0, Describe(*f->order));
    handle_frame_.erase(f->handle);
    f->order_state = OrderState::kInterrupted;
    modules_->Halt(f->handle, now_);
  }

  void RemoveSlot(int id, const char* why) {
    Slot* s = S(id);
    if (s == nullptr) return;
    if (s->sm_id != 0) {
      log_.Add(now_, Message::Kind::kKill, "EM", "SM", s->sm_id,
               std::string(why) + ": " + s->label);
      sm_.Remove(s->sm_id);
      sm_slot_.erase(s->sm_id);
    }
    slots_.erase(id);
  }

  // Kills a frame's actions and monitors; children frames die entirely. With `keep_static` the
  // frame itself survives with its static monitors (a plan failure's scope).
  void KillFrame(int fid, Diagnosis* d, bool keep_static) {
    Frame* f = F(fid);
    if (f == nullptr) return;
    for (int child : ChildFrames(fid)) {
      KillFrame(child, d, false);
      frames_.erase(child);
    }
    f = F(fid);
    if (f->order_state == OrderState::kRunning) {
      if (d != nullptr) d->halted.push_back(Describe(*f->order));
      HaltOrder(f);
    }
    for (auto& [id, a] : activities_) {
      if (a.frame == fid && a.alive) a.alive = false;
    }
    for (int sid : SlotsOf(fid)) {
      Slot* s = S(sid);
      if (keep_static && s->is_static) {
        if (s->state == Slot::State::kAwaitingReport || s->state == Slot::State::kControlRunning ||
            s->state == Slot::State::kDone) {
          s->state = Slot::State::kIdle;
          s->awaiting.clear();
          if (s->sm_id != 0) {
            sm_.Remove(s->sm_id);
            sm_slot_.erase(s->sm_id);
            s->sm_id = 0;
          }
        }
        continue;
      }
      if (d != nullptr && s->sm_id != 0) d->cancelled_monitors.push_back(s->label);
      RemoveSlot(sid, "killed with its action");
    }
  }

  // A command or sub-mission ends normally: it dies and the activity that waits on it goes on.
  void EndFrame(int fid) {
    Frame* f = F(fid);
    if (f == nullptr) return;
    const int owner = f->owner;
    KillFrame(fid, nullptr, false);
    frames_.erase(fid);
    Resume(owner, fid);
    // An order ended: activities waiting for a resource may start.
    for (auto& [id, a] : activities_) {
      if (a.alive && a.wait == Wait::kResource) {
        a.wait = Wait::kNone;
        queue_.push_back(RunEvent(id));
      }
    }
  }

  void Resume(int activity, int frame) {
    Activity* a = A(activity);
    if (a != nullptr && a->alive && a->wait == Wait::kFrame && a->wait_frame == frame) {
      a->wait = Wait::kNone;
      queue_.push_back(RunEvent(activity));
    }
  }

  // A command whose order no longer runs ends once its control actions are over.
  void MaybeEndCommand(int fid) {
    Frame* f = F(fid);
    if (f == nullptr || f->kind != FrameKind::kCommand) return;
    if (f->order_state != OrderState::kInterrupted && f->order_state != OrderState::kFailed) return;
    for (const auto& [id, a] : activities_) {
      if (a.alive && a.frame == fid) return;
    }
    for (const auto& [id, s] : slots_) {
      if (s.frame == fid && s.state == Slot::State::kAwaitingReport) return;
    }
    if (f->order_state == OrderState::kFailed) {
      MissionFail(f->failure, f->failure_where);
      return;
    }
    Note("the order " + Describe(*f->order) +
         " was interrupted and not resumed: the next statement runs");
    EndFrame(fid);
  }

  // --- monitors ---------------------------------------------------------------------------------
  int NewSlot(const Monitor* m, const std::string& file, int frame, bool o) {
    Slot s;
    s.id = NewId();
    s.ast = m;
    s.file = file;
    s.frame = frame;
    s.o_surveillance = o;
    s.terminal = IsTerminal(*m);
    s.is_static = m->is_static;
    s.label = std::string(m->is_static ? "MNTR STATIC " : "MNTR ") + m->condition.ToText() +
              " at " + Where(file, m->where);
    slots_[s.id] = s;
    return s.id;
  }

  // Messages 2, 3, control action stored, 4.
  bool Arm(int sid, SurveillanceManager::Activation mode, std::string* error) {
    Slot* s = S(sid);
    const int sonar_count = static_cast<int>(sm_.ring().mounts.size());
    Decoded<CompiledCondition> c = DecodeCondition(s->ast->condition, resolver(), sonar_count);
    if (!c.ok()) {
      *error = Where(s->file, c.where.line > 0 ? c.where : s->ast->where) + ": " + c.error;
      return false;
    }
    MonitorRequest request;
    request.label = s->label;
    request.condition = std::move(c.value);
    for (const Statement& r : s->ast->reflex) {
      Decoded<OperatorCommand> d = DecodeOperator(r, resolver());
      if (!d.ok()) {
        *error = Where(s->file, d.where.line > 0 ? d.where : r.where) + ": " +
                 (d.error.empty() ? "the reflex's arguments are unknown" : d.error);
        return false;
      }
      request.reflex.push_back(std::move(d.value));
    }
    request.o_surveillance = s->o_surveillance;
    request.terminal = s->terminal;
    request.is_static = s->is_static;
    request.rank = static_cast<long>(s->ast->where.line) * 10000 + s->ast->where.column;
    log_.Add(now_, Message::Kind::kMonitor, "EM", "SM", 0, s->label);
    const MonitorId id = sm_.Register(std::move(request), now_);
    s = S(sid);
    s->sm_id = id;
    s->state = Slot::State::kActive;
    sm_slot_[id] = sid;
    if (log_.enabled()) {
      std::string control;
      for (const Statement& st : s->ast->control) control += st.ToText();
      log_.Add(now_, Message::Kind::kControlStored, "EM", "", id,
               "control action stored: " + Shorten(control.empty() ? "none" : control, 80));
    }
    sm_.Activate(id, now_, mode);
    return true;
  }

  std::string ReflexText(const Slot& s) {
    std::string out;
    for (const Statement& r : s.ast->reflex) out += r.ToText();
    return out.empty() ? "()" : out;
  }

  void HandleFired(const Firing& firing) {
    auto it = sm_slot_.find(firing.id);
    if (it == sm_slot_.end()) {
      sm_.Remove(firing.id);
      return;
    }
    Slot* s = S(it->second);
    if (s == nullptr || s->state != Slot::State::kActive) {
      sm_.Remove(firing.id);
      sm_slot_.erase(firing.id);
      if (s != nullptr) s->sm_id = 0;
      return;
    }
    MonitorEvent e;
    e.time_s = now_;
    e.id = firing.id;
    e.label = s->label;
    e.condition = s->ast->condition.ToText();
    e.reflex = ReflexText(*s);
    e.o_surveillance = s->o_surveillance;
    e.terminal = s->terminal;
    e.is_static = s->is_static;
    for (const Statement& c : s->ast->control) {
      e.control += (e.control.empty() ? "" : " ") + c.ToText();
    }
    e.command = CommandText(F(TargetOfSlot(*s)));
    fired_.push_back(e);
    pending_events_.push_back(e);
    s->state = Slot::State::kAwaitingReport;
    s->awaiting.clear();
    if (s->terminal) {
      // The stop went to the modules: wait for the report that the current action is
      // interrupted (Fig. 5, 7) before the control action runs.
      for (const auto& [id, f] : frames_) {
        if (f.order_state == OrderState::kRunning && f.stop_requested) {
          s->awaiting.push_back(f.handle);
        }
      }
    }
    if (!s->awaiting.empty()) s->deadline = now_ + parameters_.interruption_report_timeout_s;
    proceed_queue_.push_back(s->id);
    PumpProceed();
  }

  // Control actions run in the order their monitors fired (the priority order for simultaneous
  // firings): one waits while an earlier one still waits for its interruption report.
  void PumpProceed() {
    if (pumping_) return;
    pumping_ = true;
    while (!proceed_queue_.empty()) {
      const int sid = proceed_queue_.front();
      Slot* s = S(sid);
      if (s == nullptr || s->state != Slot::State::kAwaitingReport) {
        proceed_queue_.pop_front();
        continue;
      }
      if (!s->awaiting.empty()) break;
      proceed_queue_.pop_front();
      Proceed(sid);
    }
    pumping_ = false;
  }

  // Destroys the fired monitor and runs its control action.
  void Proceed(int sid) {
    Slot* s = S(sid);
    if (s == nullptr) return;
    if (s->sm_id != 0) {
      log_.Add(now_, Message::Kind::kDestroy, "EM", "SM", s->sm_id, s->label);
      sm_.Remove(s->sm_id);
      sm_slot_.erase(s->sm_id);
    }
    const MonitorId was = s->sm_id;
    s->sm_id = 0;
    s->awaiting.clear();
    if (s->ast->control.empty()) {
      s->state = Slot::State::kDone;
      log_.Add(now_, Message::Kind::kControlAction, "EM", "", was, "no control action");
      const int target = TargetOfSlot(*s);
      AfterControl(sid);
      MaybeEndCommand(target);
      return;
    }
    log_.Add(now_, Message::Kind::kControlAction, "EM", "", was,
             Shorten(s->ast->ToText().substr(s->ast->ToText().find("=>")), 100));
    Activity a;
    a.id = NewId();
    a.frame = s->frame;
    a.slot = sid;
    a.stack.push_back(Cursor{&s->ast->control, 0, nullptr});
    activities_[a.id] = a;
    s->state = Slot::State::kControlRunning;
    s->activity = a.id;
    RunActivity(a.id);
  }

  // A control action ended normally: a static monitor becomes active again (next datum), an
  // O-surveillance once its condition has been false; the others are done (Fig. 5).
  void AfterControl(int sid) {
    Slot* s = S(sid);
    if (s == nullptr || F(s->frame) == nullptr) return;
    if (!s->o_surveillance && !s->is_static) {
      slots_.erase(sid);
      return;
    }
    if (s->sm_id != 0) return;
    std::string error;
    const auto mode = s->o_surveillance ? SurveillanceManager::Activation::kAfterFalse
                                        : SurveillanceManager::Activation::kNextDatum;
    if (!Arm(sid, mode, &error)) {
      Note("monitor not re-armed: " + error);
      if (!s->o_surveillance) {
        MissionFail(error, Where(s->file, s->ast->where));
      }
    }
  }

  // --- reports ----------------------------------------------------------------------------------
  void HandleReport(OperatorHandle handle, const OperatorReply& reply) {
    auto it = handle_frame_.find(handle);
    Frame* f = it == handle_frame_.end() ? nullptr : F(it->second);
    if (f == nullptr || f->order_state != OrderState::kRunning || f->handle != handle) {
      Note("report on operator " + std::to_string(handle) + " (" + StatusName(reply.status) +
           ") ignored: not running");
      return;
    }
    if (reply.status == OperatorStatus::kRunning) return;
    log_.Add(now_, Message::Kind::kReport, ModuleName(*f->order), "EM", 0,
             Describe(*f->order) + ": " + StatusName(reply.status) +
                 (reply.message.empty() ? "" : " (" + reply.message + ")"));
    for (const auto& [name, value] : reply.results) vars_[name] = value;
    handle_frame_.erase(it);
    const int fid = f->id;
    switch (reply.status) {
      case OperatorStatus::kCompleted:
        f->order_state = OrderState::kCompleted;
        EndFrame(fid);
        return;
      case OperatorStatus::kFailed:
        f->order_state = OrderState::kFailed;
        PlanFailure(fid,
                    ModuleName(*f->order) + " reported that " + Describe(*f->order) + " failed" +
                        (reply.message.empty() ? "" : ": " + reply.message),
                    Where(FileOfFrame(fid), f->statement->where));
        return;
      case OperatorStatus::kInterrupted:
        break;
      case OperatorStatus::kRunning:
        return;
    }
    f->order_state = OrderState::kInterrupted;
    if (!f->stop_requested) {
      f->order_state = OrderState::kFailed;
      PlanFailure(fid,
                  ModuleName(*f->order) + " interrupted " + Describe(*f->order) +
                      " though no monitor stopped it",
                  Where(FileOfFrame(fid), f->statement->where));
      return;
    }
    // A stop reflex interrupted it. A command inside a control action dies with that control
    // action; a command of MAIN stays, waiting for its monitor's decision.
    Activity* owner = A(f->owner);
    if (owner != nullptr && !owner->is_main) {
      Note("the stop interrupted " + Describe(*f->order) + ": its control action ends");
      const int owner_slot = owner->slot;
      const int owner_frame = owner->frame;
      owner->alive = false;
      KillFrame(fid, nullptr, false);
      frames_.erase(fid);
      if (owner_slot != 0 && S(owner_slot) != nullptr) AfterControl(owner_slot);
      ReleaseAwaiting(handle);
      MaybeEndCommand(owner_frame);
      return;
    }
    ReleaseAwaiting(handle);
    MaybeEndCommand(fid);
  }

  void ReleaseAwaiting(OperatorHandle handle) {
    for (auto& [id, s] : slots_) {
      if (s.state != Slot::State::kAwaitingReport) continue;
      auto h = std::find(s.awaiting.begin(), s.awaiting.end(), handle);
      if (h != s.awaiting.end()) s.awaiting.erase(h);
    }
    PumpProceed();
  }

  const std::string& FileOfFrame(int fid) {
    static const std::string kNone;
    if (InTree(fid, o_root_) && o_file_) return o_file_->file;
    return mission_file_ ? mission_file_->file : kNone;
  }

  // --- ENV --------------------------------------------------------------------------------------
  bool EnvHolds(const OperatorSpec& spec, std::string* why) {
    for (const auto& [name, value] : spec.required_env) {
      const Lookup l = Resolve(name);
      if (l.kind != Lookup::Kind::kValue || l.value != value) {
        *why = "(" + name + " " + value.ToText() + ") does not hold: " + name + " is " +
               Shorten(l.value.ToText(), 40);
        return false;
      }
    }
    return true;
  }

  void HandleEnvCheck() {
    std::vector<int> ids;
    for (const auto& [id, f] : frames_) {
      if (f.order_state == OrderState::kRunning && f.spec != nullptr &&
          !f.spec->required_env.empty()) {
        ids.push_back(id);
      }
    }
    for (int id : ids) {
      Frame* f = F(id);
      if (f == nullptr || f->order_state != OrderState::kRunning) continue;
      std::string why;
      if (EnvHolds(*f->spec, &why)) continue;
      const std::string cause = "the execution environment of " + f->spec->name + " " + why +
                                ": the executive stops the task";
      log_.Add(now_, Message::Kind::kEnv, "EM", "", 0, cause);
      HaltOrder(f);
      f->order_state = OrderState::kFailed;
      PlanFailure(id, cause, Where(FileOfFrame(id), f->statement->where));
    }
  }

  // --- failures ---------------------------------------------------------------------------------
  // A plan failure of the command `fid` (section 4.2): the executive cancels the current action
  // and the related monitors but the static ones, which stay or become active again at once;
  // one that fires decides in its control action, otherwise the diagnostic step fails the
  // mission.
  void PlanFailure(int fid, const std::string& cause, const std::string& where) {
    if (state_ != MissionState::kRunning || !InTree(fid, root_mission_)) {
      Note("failure outside a mission: " + cause);
      Frame* f = F(fid);
      if (f != nullptr && f->kind == FrameKind::kCommand) EndFrame(fid);
      return;
    }
    const int sid = TopCommand(fid);
    Frame* s = F(sid);
    log_.Add(now_, Message::Kind::kNote, "EM", "", 0, "plan failure: " + cause);
    if (s->kind != FrameKind::kCommand || s->in_failure) {
      MissionFail(s->in_failure ? cause + " (while recovering from: " + s->failure + ")" : cause,
                  where);
      return;
    }
    s->in_failure = true;
    s->failure = cause;
    s->failure_where = where;
    KillFrame(sid, nullptr, true);
    s = F(sid);
    s->order_state = OrderState::kFailed;
    bool decided = false;
    for (int slot_id : SlotsOf(sid)) {
      Slot* slot = S(slot_id);
      if (!slot->is_static) continue;
      if (slot->sm_id != 0) {  // active: evaluated again at once, under a new identifier
        sm_.Remove(slot->sm_id);
        sm_slot_.erase(slot->sm_id);
        slot->sm_id = 0;
      }
      std::string error;
      if (!Arm(slot_id, SurveillanceManager::Activation::kAtOnce, &error)) {
        Note("static monitor not re-armed: " + error);
        continue;
      }
      slot = S(slot_id);
      log_.Add(now_, Message::Kind::kNote, "EM", "", slot->sm_id,
               "static monitor active again after the failure: " + slot->label);
      if (!sm_.IsActive(slot->sm_id)) decided = true;  // fired at once
    }
    if (!decided) MissionFail(cause, where);  // the diagnostic step: the failure stands
  }

  // FAIL (section 5): the whole mission stops; every non-static monitor is cancelled; the
  // diagnostic step reports. Without a diagnostic module's recovery plan (the paper's DM is not
  // implemented either) the mission ends failed and its static monitors go with it.
  void MissionFail(const std::string& cause, const std::string& where) {
    if (state_ != MissionState::kRunning) {
      Note("FAIL without a running mission: " + cause);
      return;
    }
    Diagnosis d;
    d.time_s = now_;
    d.cause = cause;
    d.where = where;
    d.fired = fired_;
    std::vector<int> frames;
    CollectTree(root_mission_, &frames);
    for (int fid : frames) {
      Frame* f = F(fid);
      if (f != nullptr && f->order_state == OrderState::kRunning) {
        d.halted.push_back(Describe(*f->order));
        HaltOrder(f);
      }
    }
    for (auto& [id, a] : activities_) {
      if (std::find(frames.begin(), frames.end(), a.frame) != frames.end()) a.alive = false;
    }
    for (int fid : frames) {
      for (int sid : SlotsOf(fid)) {
        Slot* s = S(sid);
        if (s->is_static) {
          d.static_monitors.push_back(s->label);
          continue;
        }
        if (s->sm_id != 0) d.cancelled_monitors.push_back(s->label);
        RemoveSlot(sid, "cancelled by FAIL");
      }
    }
    log_.Add(now_, Message::Kind::kDiagnosis, "EM", "DM", 0,
             "cause: " + cause + (where.empty() ? "" : " at " + where) + "; " +
                 std::to_string(d.fired.size()) + " monitor(s) fired");
    diagnosis_ = d;
    state_ = MissionState::kFailed;
    log_.Add(now_, Message::Kind::kMission, "EM", "", 0,
             "mission " + mission_name_ +
                 " failed (no recovery plan: the static monitors "
                 "end with the mission)");
    KillTree(root_mission_);
  }

  void MissionSucceed() {
    log_.Add(now_, Message::Kind::kMission, "EM", "", 0, "mission " + mission_name_ + " succeeded");
    state_ = MissionState::kSucceeded;
    KillTree(root_mission_);
  }

  void CollectTree(int fid, std::vector<int>* out) {
    if (F(fid) == nullptr) return;
    out->push_back(fid);
    for (int child : ChildFrames(fid)) CollectTree(child, out);
  }

  void KillTree(int root) {
    if (F(root) == nullptr) return;
    KillFrame(root, nullptr, false);
    frames_.erase(root);
    for (auto it = activities_.begin(); it != activities_.end();) {
      it = it->second.alive ? std::next(it) : activities_.erase(it);
    }
  }

  void CleanupMissionTree() {
    if (root_mission_ != 0 && F(root_mission_) != nullptr) KillTree(root_mission_);
    for (auto it = activities_.begin(); it != activities_.end();) {
      it = it->second.alive ? std::next(it) : activities_.erase(it);
    }
  }

  // --- activities -------------------------------------------------------------------------------
  void RunActivity(int aid) {
    Activity* a = A(aid);
    if (a == nullptr || !a->alive || a->running || a->wait != Wait::kNone) return;
    a->running = true;
    while (true) {
      a = A(aid);
      if (a == nullptr || !a->alive || a->wait != Wait::kNone) break;
      if (a->stack.empty()) {
        a->running = false;
        FinishActivity(aid);
        return;
      }
      Cursor& c = a->stack.back();
      if (c.index >= c.body->size()) {
        if (c.loop != nullptr) {
          a->wait = Wait::kStep;  // one iteration per Step
          break;
        }
        a->stack.pop_back();
        continue;
      }
      const Statement& st = (*c.body)[c.index];
      ++c.index;
      Execute(aid, st);
    }
    a = A(aid);
    if (a != nullptr) a->running = false;
  }

  void FinishActivity(int aid) {
    Activity* a = A(aid);
    if (a == nullptr) return;
    a->alive = false;
    const int frame = a->frame;
    const int slot = a->slot;
    if (a->is_main) {
      if (frame == root_mission_) {
        MissionSucceed();
      } else {
        EndFrame(frame);
      }
      return;
    }
    int target = 0;
    if (slot != 0 && S(slot) != nullptr) {
      target = TargetOfSlot(*S(slot));
      S(slot)->state = Slot::State::kDone;
      S(slot)->activity = 0;
      AfterControl(slot);
    }
    MaybeEndCommand(frame);
    if (target != frame) MaybeEndCommand(target);
  }

  void RuntimeFailure(int aid, const Statement& st, const std::string& error) {
    Activity* a = A(aid);
    const std::string where = Where(a != nullptr ? FileOf(*a) : std::string(), st.where);
    if (a == nullptr) return;
    // Make the failure belong to a command: the statement's own if it is one.
    Frame f;
    f.id = NewId();
    f.kind = FrameKind::kCommand;
    f.parent = a->frame;
    f.statement = &st;
    f.owner = aid;
    f.order_state = OrderState::kFailed;
    frames_[f.id] = f;
    a->wait = Wait::kFrame;
    a->wait_frame = f.id;
    PlanFailure(f.id, error, where);
  }

  void Execute(int aid, const Statement& st) {
    Activity* a = A(aid);
    const std::string& file = FileOf(*a);
    switch (st.kind) {
      case Statement::Kind::kSet: {
        const Decoded<Value> v = ResolveValueExpr(st.value, resolver());
        if (!v.ok()) {
          RuntimeFailure(aid, st, v.error);
          return;
        }
        vars_[st.target] = v.value;
        Note("set " + st.target + " " + Shorten(v.value.ToText(), 60));
        Event e;
        e.kind = Event::Kind::kEnvCheck;
        queue_.push_back(e);
        return;
      }
      case Statement::Kind::kIf: {
        const bool t = EvalTest(st.test, file);
        A(aid)->stack.push_back(Cursor{t ? &st.then_body : &st.else_body, 0, nullptr});
        return;
      }
      case Statement::Kind::kWhile:
        if (EvalTest(st.test, file)) A(aid)->stack.push_back(Cursor{&st.then_body, 0, &st});
        return;
      case Statement::Kind::kNext:
        DoNext(aid);
        return;
      case Statement::Kind::kFail: {
        Slot* s = S(a->slot);
        const std::string cause =
            "FAIL in the control action of " + (s != nullptr ? s->label : std::string("MAIN"));
        if (s != nullptr && s->o_surveillance && state_ != MissionState::kRunning) {
          Note("O-surveillance FAIL with no mission running: " + s->label);
          return;
        }
        MissionFail(cause, Where(file, st.where));
        return;
      }
      case Statement::Kind::kMonitor: {
        const int slot = NewSlot(st.monitor.get(), file, a->frame, a->frame == o_root_);
        std::string error;
        if (!Arm(slot, SurveillanceManager::Activation::kNextDatum, &error)) {
          slots_.erase(slot);
          RuntimeFailure(aid, st, error);
        }
        return;
      }
      case Statement::Kind::kMission:
        StartSubMission(aid, st);
        return;
      case Statement::Kind::kCommand:
      case Statement::Kind::kRun:
        if (st.op == "resume-order") {
          DoResume(aid);
        } else {
          StartOperator(aid, st);
        }
        return;
    }
  }

  void StartSubMission(int aid, const Statement& st) {
    const Mission& m = *st.mission;
    for (const Test& t : m.pre) {
      if (!EvalTest(t, FileOf(*A(aid)))) {
        RuntimeFailure(
            aid, st,
            "sub-mission " + m.name + ": PRE: " + t.ToText() + " does not hold" + Explain(t));
        return;
      }
    }
    Activity* a = A(aid);
    const int fid = StartMissionFrame(m, a->frame, aid);
    a = A(aid);
    if (F(fid) != nullptr) {
      a->wait = Wait::kFrame;
      a->wait_frame = fid;
    }
  }

  bool ResourceBusy(const OperatorSpec& spec) {
    for (const auto& [id, f] : frames_) {
      if (f.order_state != OrderState::kRunning || f.spec == nullptr) continue;
      for (const std::string& r : spec.resources) {
        if (std::find(f.spec->resources.begin(), f.spec->resources.end(), r) !=
            f.spec->resources.end()) {
          return true;
        }
      }
    }
    return false;
  }

  void StartOperator(int aid, const Statement& st) {
    const OperatorSpec* spec = FindOperator(st.op);
    Decoded<OperatorCommand> d = DecodeOperator(st, resolver());
    if (spec == nullptr || !d.ok()) {
      RuntimeFailure(aid, st, d.error.empty() ? "the operator's arguments are unknown" : d.error);
      return;
    }
    if (spec->long_running && ResourceBusy(*spec)) {
      // A concurrent action waits while the current action holds the same resource.
      Activity* a = A(aid);
      --a->stack.back().index;
      a->wait = Wait::kResource;
      return;
    }
    std::string why;
    if (!EnvHolds(*spec, &why)) {
      RuntimeFailure(aid, st, "the execution environment of " + spec->name + " " + why);
      return;
    }
    Frame f;
    f.id = NewId();
    f.kind = FrameKind::kCommand;
    f.parent = A(aid)->frame;
    f.statement = &st;
    f.owner = aid;
    f.order = d.value;
    f.spec = spec;
    f.handle = ++next_handle_;
    const int fid = f.id;
    frames_[fid] = f;
    SendOrder(fid, aid, true);
  }

  void SendOrder(int fid, int aid, bool create_monitors) {
    Frame* f = F(fid);
    const OperatorCommand command = *f->order;
    const OperatorHandle handle = f->handle;
    log_.Add(now_, Message::Kind::kOperator, "EM", ModuleName(command), 0, Describe(command));
    f->order_state = OrderState::kRunning;
    f->stop_requested = false;
    handle_frame_[handle] = fid;
    auto wait_on_order = [&] {
      Activity* owner = A(aid);
      if (owner != nullptr && owner->alive && aid == F(fid)->owner) {
        owner->wait = Wait::kFrame;
        owner->wait_frame = fid;
      }
    };
    if (f->spec->long_running) wait_on_order();
    const OperatorReply reply = modules_->Send(handle, command, now_);
    f = F(fid);
    if (f == nullptr || f->handle != handle || f->order_state != OrderState::kRunning) return;
    for (const auto& [name, value] : reply.results) vars_[name] = value;
    switch (reply.status) {
      case OperatorStatus::kRunning:
        if (!f->spec->long_running) {
          Note(f->spec->name + " answered 'running' though it is done at once: taken as done");
          handle_frame_.erase(handle);
          f->order_state = OrderState::kCompleted;
          EndFrame(fid);
          return;
        }
        if (create_monitors && f->statement != nullptr) {
          const std::string& file = FileOfFrame(fid);
          for (const Monitor& m : f->statement->monitors) {
            const int slot = NewSlot(&m, file, fid, false);
            std::string error;
            if (!Arm(slot, SurveillanceManager::Activation::kNextDatum, &error)) {
              slots_.erase(slot);
              HaltOrder(F(fid));
              F(fid)->order_state = OrderState::kFailed;
              PlanFailure(fid, error, Where(file, m.where));
              return;
            }
            if (F(fid) == nullptr) return;
          }
        }
        return;
      case OperatorStatus::kCompleted:
        handle_frame_.erase(handle);
        f->order_state = OrderState::kCompleted;
        EndFrame(fid);
        return;
      case OperatorStatus::kInterrupted:
      case OperatorStatus::kFailed:
        handle_frame_.erase(handle);
        f->order_state = OrderState::kFailed;
        wait_on_order();  // the activity waits for the failure's decision
        PlanFailure(fid,
                    ModuleName(command) + " refused " + Describe(command) +
                        (reply.message.empty() ? "" : ": " + reply.message),
                    Where(FileOfFrame(fid), f->statement->where));
        return;
    }
  }

  void DoNext(int aid) {
    const int target = TargetOf(aid);
    Frame* t = F(target);
    if (t == nullptr) {
      Note("NEXT: no current action");
      return;
    }
    Note("NEXT: " + (t->order ? Describe(*t->order) : std::string("the command")) +
         " stops, its monitors are killed, the next command runs");
    EndFrame(target);
  }

  void DoResume(int aid) {
    const int target = TargetOf(aid);
    Frame* t = F(target);
    if (t == nullptr || !t->order) {
      Note("resume-order: no interrupted order");
      return;
    }
    if (t->order_state == OrderState::kRunning || t->order_state == OrderState::kCompleted) {
      Note("resume-order: " + Describe(*t->order) + " is not interrupted");
      return;
    }
    if (auto* move = std::get_if<SmoothMoveCommand>(&*t->order)) move->resume = true;
    std::string why;
    if (!EnvHolds(*t->spec, &why)) {
      t->order_state = OrderState::kFailed;
      t->in_failure = false;
      PlanFailure(target, "resume-order: the execution environment of " + t->spec->name + " " + why,
                  Where(FileOfFrame(target), t->statement->where));
      return;
    }
    t->in_failure = false;
    t->failure.clear();
    t->handle = ++next_handle_;
    SendOrder(target, t->owner, false);  // its monitors are still there
  }

  ExecutiveParameters parameters_;
  RobotModules* modules_;
  MessageLog log_;
  SurveillanceManager sm_;
  OperatorHandle next_handle_ = 0;
  int next_id_ = 0;
  int depth_ = 0;
  double now_ = 0.0;
  std::deque<Event> queue_;
  std::deque<int> proceed_queue_;
  bool pumping_ = false;

  std::shared_ptr<const MissionFile> mission_file_;
  std::shared_ptr<const MissionFile> o_file_;
  std::map<std::string, Value> vars_, o_defs_, robot_state_, world_;
  std::set<std::string> assigned_;
  int o_root_ = 0;
  int root_mission_ = 0;
  std::map<int, Frame> frames_;
  std::map<int, Activity> activities_;
  std::map<int, Slot> slots_;
  std::map<MonitorId, int> sm_slot_;
  std::map<OperatorHandle, int> handle_frame_;
};

// --- Executive
// ------------------------------------------------------------------------------------

Executive::Executive(const ExecutiveParameters& parameters,
                     const SurveillanceParameters& surveillance, const SonarRing& ring,
                     RobotModules* modules) {
  std::vector<std::string> errors = ValidateParameters(parameters);
  for (const std::string& e : ValidateParameters(surveillance)) errors.push_back(e);
  if (modules == nullptr) errors.push_back("modules: must not be null");
  if (!errors.empty()) {
    std::string all;
    for (const std::string& e : errors) all += e + "; ";
    throw std::invalid_argument("Executive: " + all);
  }
  impl_ = std::make_unique<Impl>(parameters, surveillance, ring, modules);
}

Executive::~Executive() = default;

void Executive::SetWorldVariable(const std::string& name, Value value) {
  impl_->SetWorldVariable(name, std::move(value));
}
void Executive::SetWorldZone(const std::string& name, const std::vector<Point2>& polygon_m) {
  impl_->SetWorldVariable(name, PolygonToValue(polygon_m));
}
void Executive::SetRobotState(const std::string& name, Value value) {
  impl_->SetRobotState(name, std::move(value));
}
std::vector<Diagnostic> Executive::SetOSurveillances(const MissionFile& file, double now) {
  return impl_->SetOSurveillances(file, now);
}
StartResult Executive::StartMission(const MissionFile& file, double now) {
  return impl_->StartMission(file, now);
}
void Executive::Abort(const std::string& reason, double now) { impl_->Abort(reason, now); }
void Executive::OnSonar(const SonarScan& scan, double now) { impl_->OnSonar(scan, now); }
void Executive::OnPose(const PoseDatum& pose, double now) { impl_->OnPose(pose, now); }
void Executive::OnLaser(const LaserScan& scan, double now) { impl_->OnLaser(scan, now); }
void Executive::OnBattery(const BatteryDatum& battery, double now) {
  impl_->OnBattery(battery, now);
}
void Executive::OnOperatorReport(OperatorHandle handle, const OperatorReply& reply, double now) {
  impl_->OnOperatorReport(handle, reply, now);
}
void Executive::Step(double now) { impl_->Step(now); }
MissionState Executive::state() const { return impl_->state_; }
const std::string& Executive::mission_name() const { return impl_->mission_name_; }
const Diagnosis& Executive::diagnosis() const { return impl_->diagnosis_; }
const std::vector<MonitorEvent>& Executive::fired() const { return impl_->fired_; }
std::vector<MonitorEvent> Executive::TakeMonitorEvents() {
  std::vector<MonitorEvent> out;
  std::swap(out, impl_->pending_events_);
  return out;
}
std::optional<Value> Executive::Variable(const std::string& name) const {
  return impl_->Variable(name);
}
const MessageLog& Executive::log() const { return impl_->log(); }
MessageLog& Executive::log() { return impl_->log(); }
const SurveillanceManager& Executive::surveillance() const { return impl_->sm(); }
size_t Executive::active_monitors() const { return impl_->sm().active_count(); }
std::string Executive::CurrentCommand() const { return impl_->CurrentCommandText(); }
std::vector<std::string> Executive::ActiveMonitors() const { return impl_->sm().ActiveLabels(); }

}  // namespace rpl_executive::noreils_chatila
