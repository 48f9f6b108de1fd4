#include "spott_tr_plus/interpreter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "spott_tr_plus/checker.h"

namespace spott_tr_plus {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// One condition process: a named condition with its input values (SPOTT III.C.1: "a condition
/// ... is an executable process").
struct Process {
  std::string key;  ///< "name" or "name(input, ...)".
  const ConditionDecl* decl = nullptr;
  const Registry::ConditionBinding* binding = nullptr;
  // Copies of the declaration and binding read on every scan (one indirection less).
  Registry::ConditionKind kind = Registry::ConditionKind::kExternal;
  bool ballistic = false;
  double frequency_hz = 0.0;
  std::vector<Value> inputs;
  std::vector<Value> outputs;
  bool value = false;
  bool has_value = false;
  bool computing = false;
  Ticket ticket = 0;
  double last_update = -kInf;
  double next_due = -kInf;
  int refs = 0;              ///< Compiled atoms of live frames that read this process.
  uint64_t demand_pass = 0;  ///< Last scan pass that demanded the value.
  uint64_t computed_pass = 0;
  uint64_t computed_call = 0;  ///< Scan() call of the last asynchronous start.
  /// Made for the inputs a dynamic atom read (outputs to its left): dropped once no atom
  /// reads it, so changing values (poses, room ids) do not pile up processes.
  bool transient = false;
};

/// Where an input of an atom comes from: a constant (a literal or a program parameter) or an
/// output of an atom to its left in a sequential AND (SPOTT Fig. 13: "find a new room", then
/// "in that room").
struct InputSource {
  Value constant;
  int node = -1;  ///< >= 0: the atom whose output it reads
  int out = -1;   ///< that atom's output index
};

/// One compiled condition node of a frame; atoms point at their process.
struct CNode {
  CondOp op = CondOp::kTrue;
  double timeout_s = -1.0;
  Process* proc = nullptr;  ///< Null for a dynamic atom not evaluated yet.
  const CondExpr* expr = nullptr;
  int a = -1, b = -1;
  /// Atoms whose inputs read outputs bound to their left: the process (one per input values)
  /// is looked up again each time the atom is evaluated.
  bool dynamic = false;
  std::vector<InputSource> sources;
};

/// An output variable of a rule's condition: atom `node`'s output `out`.
struct Binding {
  std::string var;
  int node = -1;
  int out = -1;
};

struct Frame;

/// One executing action expression (a tree mirroring the ActExpr).
struct Run {
  const ActExpr* expr = nullptr;
  Run* parent = nullptr;
  std::vector<std::unique_ptr<Run>> kids;
  size_t seq_index = 0;
  bool done = false;
  Ticket ticket = 0;     ///< Running primitive action.
  int callee = -1;       ///< Frame id of a called subroutine.
  int owner_frame = -1;  ///< Root only: the frame and rule that started it.
  int rule = -1;
  bool ballistic = false;
  std::vector<Value> args;           ///< Primitive action or call: the arguments it started with.
  uint64_t done_call = 0;            ///< Root only: the Scan() call in which it completed.
  uint64_t started_call = 0;         ///< Root only: the Scan() call in which it started.
  std::map<std::string, Value> env;  ///< Root only: variables bound when the action started.
};

struct Frame {
  int id = 0;
  int program = -1;
  std::vector<Value> args;
  std::map<std::string, Value> params;
  int depth = 0;
  int caller_frame = -1;
  Run* caller_run = nullptr;  ///< The call leaf this frame completes.
  std::vector<CNode> nodes;
  std::vector<int> roots;                      ///< Per rule: root node of its condition.
  std::vector<std::vector<Binding>> bindings;  ///< Per rule: its condition's output variables.
  /// Per rule: indices into bindings[rule] of the variables its action reads (a change of
  /// their values restarts a sustained action with the new values).
  std::vector<std::vector<int>> watched;
  std::vector<char> values, prev_values, armed;
  int firing = -1;
  std::unique_ptr<Run> energized;
  int energized_rule = -1;
  std::vector<std::unique_ptr<Run>> ballistic;
  bool dynamic = false;  ///< Some atom's process follows the outputs to its left.
};

Value ArgValue(const Arg& a, const std::map<std::string, Value>& env) {
  switch (a.kind) {
    case Arg::Kind::kNumber:
      return a.number;
    case Arg::Kind::kString:
      return a.text;
    case Arg::Kind::kVariable: {
      auto it = env.find(a.text);
      return it == env.end() ? Value{} : it->second;
    }
  }
  return Value{};
}

}  // namespace

struct Interpreter::Impl {
  ProgramFile file;
  Registry registry;
  Options options;
  std::set<std::string> off;  // options.off_subroutines
  std::string main_name;
  int main_program = -1;

  std::map<std::string, std::unique_ptr<Process>> processes;
  std::map<Ticket, Process*> condition_tickets;
  std::map<Ticket, Run*> action_tickets;
  std::map<int, std::unique_ptr<Frame>> frames;
  int next_frame_id = 0;
  Ticket next_ticket = 1;
  uint64_t scans = 0;
  uint64_t pass = 0;
  uint64_t scan_calls = 0;
  double now = 0.0;
  double next_wake = kInf;
  bool in_scan = false;
  bool dirty = false;
  bool started = false;
  std::vector<Process*> demanded;
  std::vector<int> completed_frames;
  std::vector<int> scan_ids;
  /// Per program and rule: the variables its action reads.
  std::vector<std::vector<std::set<std::string>>> action_vars;
  /// While an action is replaced, released processes are forgotten only after the new action
  /// has started, so the conditions both actions' subroutines read keep their values.
  int hold_releases = 0;
  std::vector<Process*> held;
  std::vector<std::string> garbage;  ///< Keys of forgotten transient processes.

  /// What a leaf of a new action takes over from the action it replaces: a running primitive
  /// action (its ticket) or a called subroutine's frame, possibly at its goal (`done`).
  struct Adopted {
    std::string action;  ///< the primitive action's name
    Ticket ticket = 0;
    int callee = -1;
    bool done = false;
  };
  std::map<const Run*, Adopted> adoptions;

  // --- Frames ---------------------------------------------------------------------------------

  // The process of condition `d` with these input values (one per declared input).
  Process* GetProcess(const ConditionDecl* d, std::vector<Value> inputs) {
    std::string key = d->name;
    if (!inputs.empty()) {
      key += "(";
      for (size_t k = 0; k < inputs.size(); ++k) key += (k ? ", " : "") + ValueToString(inputs[k]);
      key += ")";
    }
    auto& slot = processes[key];
    if (!slot) {
      slot = std::make_unique<Process>();
      slot->key = key;
      slot->decl = d;
      slot->binding = registry.FindCondition(d->name);
      slot->kind = slot->binding->kind;
      slot->ballistic = d->semantics == Semantics::kBallistic;
      slot->frequency_hz = d->frequency_hz;
      slot->inputs = std::move(inputs);
      slot->outputs.resize(d->NumOutputs());
    }
    return slot.get();
  }

  // Compiles condition c of a rule into f's nodes, left to right; `bindings` collects the
  // rule's output variables as they are bound (the checker made sure that an input reading one
  // is to its right across a sequential AND).
  int Compile(Frame& f, const CondExpr& c, std::vector<Binding>& bindings) {
    CNode n;
    n.op = c.op;
    n.timeout_s = c.timeout_s;
    n.expr = &c;
    const int index = static_cast<int>(f.nodes.size());
    if (c.op == CondOp::kAtom) {
      const ConditionDecl* d = file.FindCondition(c.name);
      std::vector<Value> constants;
      int out = 0;
      for (size_t k = 0; k < d->params.size(); ++k) {
        const Arg* arg = ArgForParam(c, *d, k);
        if (d->params[k].is_output) {
          if (arg) bindings.push_back(Binding{arg->text, index, out});
          ++out;
          continue;
        }
        InputSource src;
        if (arg && arg->kind == Arg::Kind::kVariable && !f.params.count(arg->text)) {
          for (auto b = bindings.rbegin(); b != bindings.rend(); ++b) {
            if (b->var == arg->text && b->node != index) {
              src.node = b->node;
              src.out = b->out;
              n.dynamic = true;
              break;
            }
          }
        } else if (arg) {
          src.constant = ArgValue(*arg, f.params);
        }
        constants.push_back(src.constant);
        n.sources.push_back(std::move(src));
      }
      if (n.dynamic) {
        f.dynamic = true;
      } else {
        n.sources.clear();
        n.proc = GetProcess(d, std::move(constants));
        ++n.proc->refs;
      }
    }
    f.nodes.push_back(n);
    if (!c.children.empty()) {
      const int a = Compile(f, c.children[0], bindings);
      f.nodes[index].a = a;
    }
    if (c.children.size() > 1) {
      const int b = Compile(f, c.children[1], bindings);
      f.nodes[index].b = b;
    }
    return index;
  }

  // A dynamic atom: the process for the input values its sources hold now.
  void Rebind(Frame& f, CNode& n) {
    std::vector<Value> inputs;
    inputs.reserve(n.sources.size());
    for (const InputSource& s : n.sources) {
      if (s.node < 0) {
        inputs.push_back(s.constant);
      } else {
        const Process* from = f.nodes[s.node].proc;
        inputs.push_back(from ? from->outputs[s.out] : Value{});
      }
    }
    if (n.proc && n.proc->inputs == inputs) return;
    const size_t before = processes.size();
    Process* next = GetProcess(file.FindCondition(n.expr->name), std::move(inputs));
    if (processes.size() != before) next->transient = true;
    ++next->refs;
    if (n.proc) ReleaseProcess(n.proc);
    n.proc = next;  // read at once by the caller (Read computes it when due)
  }

  Frame* NewFrame(int program, std::vector<Value> args, int caller, Run* caller_run, int depth) {
    auto f = std::make_unique<Frame>();
    f->id = next_frame_id++;
    f->program = program;
    const Program& p = file.programs[program];
    for (size_t k = 0; k < p.params.size() && k < args.size(); ++k)
      f->params[p.params[k]] = args[k];
    f->args = std::move(args);
    f->caller_frame = caller;
    f->caller_run = caller_run;
    f->depth = depth;
    const size_t m = p.rules.size();
    f->roots.reserve(m);
    f->bindings.resize(m);
    f->watched.resize(m);
    for (size_t i = 0; i < m; ++i) {
      f->roots.push_back(Compile(*f, p.rules[i].condition, f->bindings[i]));
      const std::set<std::string>& reads = action_vars[program][i];
      for (size_t k = 0; k < f->bindings[i].size(); ++k) {
        if (reads.count(f->bindings[i][k].var)) f->watched[i].push_back(static_cast<int>(k));
      }
    }
    f->values.assign(m, 0);
    f->prev_values.assign(m, 0);
    f->armed.assign(m, 0);
    Frame* raw = f.get();
    frames.emplace(raw->id, std::move(f));
    dirty = true;
    return raw;
  }

  void ReleaseProcess(Process* p) {
    if (--p->refs > 0) return;
    if (p->binding && p->binding->kind == Registry::ConditionKind::kExternal) return;
    if (hold_releases > 0) {
      held.push_back(p);
      return;
    }
    Forget(p);
  }

  void FlushReleases() {
    std::vector<Process*> ps;
    ps.swap(held);
    for (Process* p : ps) {
      if (p->refs == 0) Forget(p);
    }
  }

  // Deactivated: stop computing and forget the value.
  void Forget(Process* p) {
    if (p->transient) garbage.push_back(p->key);
    if (p->ticket) condition_tickets.erase(p->ticket);
    p->ticket = 0;
    p->computing = false;
    p->has_value = false;
    p->value = false;
    p->last_update = -kInf;
    p->next_due = -kInf;
    std::fill(p->outputs.begin(), p->outputs.end(), Value{});
  }

  void Deactivate(int id) {
    auto it = frames.find(id);
    if (it == frames.end()) return;
    Frame& f = *it->second;
    if (f.caller_run) f.caller_run->callee = -1;
    Cancel(f.energized.get());
    f.energized.reset();
    for (auto& r : f.ballistic) Cancel(r.get());
    f.ballistic.clear();
    for (CNode& n : f.nodes) {
      if (n.proc) ReleaseProcess(n.proc);
      n.proc = nullptr;
    }
    frames.erase(id);
    dirty = true;
  }

  // --- Actions --------------------------------------------------------------------------------

  void Cancel(Run* r) {
    if (!r) return;
    if (!r->done && r->ticket) {
      action_tickets.erase(r->ticket);
      const auto* b = registry.FindAction(r->expr->name);
      if (b && b->stop) b->stop(r->ticket);
      r->ticket = 0;
    }
    // A completed call may still hold its subroutine active (KeepsCalleeActive).
    if (r->callee >= 0) {
      const int callee = r->callee;
      r->callee = -1;
      Deactivate(callee);
    }
    for (auto& k : r->kids) Cancel(k.get());
    r->done = true;
  }

  std::unique_ptr<Run> MakeRun(const ActExpr& a, Run* parent) {
    auto r = std::make_unique<Run>();
    r->expr = &a;
    r->parent = parent;
    for (const ActExpr& k : a.children) r->kids.push_back(MakeRun(k, r.get()));
    return r;
  }

  // Starts r; sets r->done when it completes at once.
  void StartRun(Run* r, const Frame& f, const std::map<std::string, Value>& env) {
    const ActExpr& a = *r->expr;
    dirty = true;
    switch (a.op) {
      case ActOp::kNil:
        r->done = true;
        return;
      case ActOp::kInvoke: {
        std::vector<Value> args;
        args.reserve(a.args.size());
        for (const Arg& arg : a.args) args.push_back(ArgValue(arg, env));
        r->args = args;
        auto adopted = adoptions.find(r);
        if (adopted != adoptions.end()) {
          const Adopted taken = adopted->second;
          adoptions.erase(adopted);
          if (Adopt(r, taken)) return;
        }
        if (a.is_call) {
          if (f.depth + 1 > options.max_call_depth) {
            r->done = true;  // Recursion guard: the call is refused (checker warned).
            return;
          }
          if (off.count(a.name)) {
            r->done = true;  // Switched off (InterpreterOptions::off_subroutines): nil.
            return;
          }
          Frame* callee =
              NewFrame(file.ProgramIndex(a.name), std::move(args), f.id, r, f.depth + 1);
          r->callee = callee->id;
          return;
        }
        const Registry::ActionBinding* b = registry.FindAction(a.name);
        if (b->instant) {
          b->instant(args, now);
          r->done = true;
          return;
        }
        r->ticket = next_ticket++;
        action_tickets[r->ticket] = r;
        b->start(ActionCall{a.name, args, now, r->ticket});
        return;
      }
      case ActOp::kParallel: {
        bool all = true;
        for (auto& k : r->kids) {
          StartRun(k.get(), f, env);
          all = all && k->done;
        }
        r->done = all;
        return;
      }
      case ActOp::kSequence:
        r->seq_index = 0;
        AdvanceSequence(r, f, env);
        return;
    }
  }

  void AdvanceSequence(Run* r, const Frame& f, const std::map<std::string, Value>& env) {
    while (r->seq_index < r->kids.size()) {
      Run* k = r->kids[r->seq_index].get();
      if (!k->done) {
        StartRun(k, f, env);
        if (!k->done) return;
      }
      ++r->seq_index;
    }
    r->done = true;
  }

  // A leaf completed asynchronously: propagate up the tree.
  // A call whose subroutine reached its goal inside a sustained (energized) action, and not in
  // a sequence that moves on from it, keeps the subroutine active: it goes on monitoring its
  // conditions (SPOTT's BUMPER_CHECK, INFRARED_CHECK called in parallel from the main program)
  // while the calling rule stays the highest true one.
  static bool KeepsCalleeActive(const Run* leaf) {
    const Run* r = leaf;
    while (r->parent) {
      if (r->parent->expr->op == ActOp::kSequence) return false;
      r = r->parent;
    }
    return !r->ballistic;
  }

  static bool HasLiveCallee(const Run* r) {
    if (r->callee >= 0) return true;
    for (const auto& k : r->kids) {
      if (HasLiveCallee(k.get())) return true;
    }
    return false;
  }

  void LeafDone(Run* r, bool keep_callee = false) {
    r->done = true;
    r->ticket = 0;
    if (!keep_callee) r->callee = -1;
    dirty = true;
    Run* p = r->parent;
    while (p) {
      if (p->expr->op == ActOp::kParallel) {
        for (auto& k : p->kids) {
          if (!k->done) return;
        }
        p->done = true;
      } else {  // sequence: start the next element in the owner's environment
        Run* root = p;
        while (root->parent) root = root->parent;
        auto fit = frames.find(root->owner_frame);
        if (fit == frames.end()) return;
        const Frame& f = *fit->second;
        ++p->seq_index;
        AdvanceSequence(p, f, root->env);
        if (!p->done) return;
      }
      r = p;
      p = p->parent;
    }
    r->done_call = scan_calls;
  }

  // Variables of a rule's action: the program's parameters and the outputs of its conditions.
  std::map<std::string, Value> RuleEnv(const Frame& f, int rule) const {
    std::map<std::string, Value> env = f.params;
    if (rule < 0) return env;
    for (const Binding& b : f.bindings[rule]) env[b.var] = OutputValue(f, b);
    return env;
  }

  static Value OutputValue(const Frame& f, const Binding& b) {
    const Process* p = f.nodes[b.node].proc;
    return p ? p->outputs[b.out] : Value{};
  }

  // True when a variable the running action of `rule` reads has a new value.
  bool BindingsChanged(const Frame& f, int rule, const Run& run) const {
    for (int k : f.watched[rule]) {
      const Binding& b = f.bindings[rule][k];
      auto it = run.env.find(b.var);
      if (it == run.env.end() || it->second != OutputValue(f, b)) return true;
    }
    return false;
  }

  std::unique_ptr<Run> PrepareRule(Frame& f, int rule, bool ballistic) {
    const Rule& r = file.programs[f.program].rules[rule];
    auto run = MakeRun(r.action, nullptr);
    run->owner_frame = f.id;
    run->rule = rule;
    run->ballistic = ballistic;
    run->env = RuleEnv(f, rule);
    run->started_call = scan_calls;
    return run;
  }

  std::unique_ptr<Run> StartRule(Frame& f, int rule, bool ballistic) {
    auto run = PrepareRule(f, rule, ballistic);
    StartRun(run.get(), f, run->env);
    if (run->done) run->done_call = scan_calls;
    return run;
  }

  // Starts rule `rule`'s action in place of `old` (f's sustained action, or null). SPOTT
  // III.C.1, footnote 11: the active conditions are those of the main program and of "the
  // currently called set of subroutines"; a subroutine that the old and the new action both
  // call (same arguments) stays in that set: it is handed to the new action, not torn down and
  // restarted, and so are primitive actions both start at once with the same arguments. The
  // rest of the old action is cancelled before the new one starts; conditions that both
  // actions' subroutines read keep their values.
  std::unique_ptr<Run> ReplaceAction(Frame& f, std::unique_ptr<Run> old, int rule, bool ballistic) {
    auto run = PrepareRule(f, rule, ballistic);
    if (old) Reserve(run.get(), run->env, old.get());
    ++hold_releases;
    Cancel(old.get());
    old.reset();
    StartRun(run.get(), f, run->env);
    // Whatever was reserved and not taken (a refused call) is cancelled now.
    for (const auto& [leaf, taken] : adoptions) Release(taken);
    adoptions.clear();
    --hold_releases;
    FlushReleases();
    if (run->done) run->done_call = scan_calls;
    dirty = true;
    return run;
  }

  // Reserves for the leaves that starting `r` starts at once (every branch of `||`, the first
  // element of `>`) the matching live leaves of `old`.
  void Reserve(Run* r, const std::map<std::string, Value>& env, Run* old) {
    const ActExpr& a = *r->expr;
    switch (a.op) {
      case ActOp::kNil:
        return;
      case ActOp::kParallel:
        for (auto& k : r->kids) Reserve(k.get(), env, old);
        return;
      case ActOp::kSequence:
        if (!r->kids.empty()) Reserve(r->kids[0].get(), env, old);
        return;
      case ActOp::kInvoke:
        break;
    }
    std::vector<Value> args;
    for (const Arg& arg : a.args) args.push_back(ArgValue(arg, env));
    Run* match = FindLiveLeaf(old, a, args);
    if (!match) return;
    Adopted taken;
    taken.action = a.name;
    taken.done = match->done;
    taken.callee = match->callee;
    if (!match->done) taken.ticket = match->ticket;
    if (taken.ticket) action_tickets.erase(taken.ticket);
    if (taken.callee >= 0) {
      auto it = frames.find(taken.callee);
      if (it != frames.end()) it->second->caller_run = nullptr;  // the old leaf is going away
    }
    match->ticket = 0;
    match->callee = -1;
    match->done = true;
    adoptions[r] = taken;
  }

  static Run* FindLiveLeaf(Run* r, const ActExpr& want, const std::vector<Value>& args) {
    const ActExpr& a = *r->expr;
    if (a.op == ActOp::kInvoke) {
      const bool live = a.is_call ? r->callee >= 0 : (!r->done && r->ticket != 0);
      return live && a.is_call == want.is_call && a.name == want.name && r->args == args ? r
                                                                                         : nullptr;
    }
    for (auto& k : r->kids) {
      if (Run* m = FindLiveLeaf(k.get(), want, args)) return m;
    }
    return nullptr;
  }

  // Leaf r takes over what it adopted; false when there is nothing left to take (it is then
  // started as usual).
  bool Adopt(Run* r, const Adopted& taken) {
    if (taken.callee >= 0) {
      auto it = frames.find(taken.callee);
      if (it == frames.end()) return false;
      it->second->caller_run = r;
      r->callee = taken.callee;
      if (taken.done) {
        // The subroutine's goal held: a monitoring call stays active; in a sequence or a
        // ballistic action the call is complete and the subroutine leaves.
        r->done = true;
        if (!KeepsCalleeActive(r)) {
          r->callee = -1;
          Deactivate(taken.callee);
        }
      }
      return true;
    }
    if (!taken.ticket) return false;
    r->ticket = taken.ticket;
    action_tickets[r->ticket] = r;
    return true;
  }

  void Release(const Adopted& taken) {
    if (taken.ticket) {
      const auto* b = registry.FindAction(taken.action);
      if (b && b->stop) b->stop(taken.ticket);
    }
    if (taken.callee >= 0) Deactivate(taken.callee);
  }

  // --- Conditions -----------------------------------------------------------------------------

  void Compute(Process* p) {
    const Registry::ConditionBinding& b = *p->binding;
    const double period = p->decl->frequency_hz > 0 ? 1.0 / p->decl->frequency_hz : 0.0;
    if (b.kind == Registry::ConditionKind::kSync) {
      p->value = b.sync(ConditionCall{p->decl->name, p->inputs, now, 0}, p->outputs);
      p->has_value = true;
      p->last_update = now;
      p->computed_pass = pass;
      p->next_due = now + period;
    } else if (b.kind == Registry::ConditionKind::kAsync && !p->computing) {
      p->computing = true;
      p->ticket = next_ticket++;
      condition_tickets[p->ticket] = p;
      p->computed_pass = pass;
      p->computed_call = scan_calls;
      b.async(ConditionCall{p->decl->name, p->inputs, now, p->ticket});
    }
  }

  bool Read(Process* p, double& oldest) {
    if (p->demand_pass != pass) {
      p->demand_pass = pass;
      demanded.push_back(p);
    }
    if (p->kind != Registry::ConditionKind::kExternal) {
      // Frequency 0: synchronous processes compute on every scan pass, asynchronous ones start
      // once per Scan() call (a re-entrant completion must not restart them in a loop).
      const bool due = p->frequency_hz <= 0.0 ? (p->kind == Registry::ConditionKind::kSync
                                                     ? p->computed_pass != pass
                                                     : p->computed_call != scan_calls)
                                              : now >= p->next_due;
      if (due) Compute(p);
    }
    oldest = std::min(oldest, p->last_update);
    if (p->computing && p->ballistic) return false;
    return p->has_value && p->value;
  }

  bool Eval(Frame& f, int node, double& oldest) {
    CNode& n = f.nodes[node];
    switch (n.op) {
      case CondOp::kTrue:
        return true;
      case CondOp::kFalse:
        return false;
      case CondOp::kAtom:
        if (n.dynamic) Rebind(f, n);
        return Read(n.proc, oldest);
      case CondOp::kNot:
        return !Eval(f, n.a, oldest);
      default:
        break;
    }
    double local = kInf;
    bool v;
    switch (n.op) {
      case CondOp::kSeqAnd:
        v = Eval(f, n.a, local) && Eval(f, n.b, local);
        break;
      case CondOp::kSeqOr:
        v = Eval(f, n.a, local) || Eval(f, n.b, local);
        break;
      case CondOp::kParAnd: {
        const bool l = Eval(f, n.a, local);
        const bool r = Eval(f, n.b, local);
        v = l && r;
        break;
      }
      case CondOp::kParOr: {
        const bool l = Eval(f, n.a, local);
        const bool r = Eval(f, n.b, local);
        v = l || r;
        break;
      }
      default: {  // kXor
        const bool l = Eval(f, n.a, local);
        const bool r = Eval(f, n.b, local);
        v = l != r;
        break;
      }
    }
    oldest = std::min(oldest, local);
    if (n.timeout_s >= 0.0) {
      // Timed operator (AND_t, OR_t, XOR_t): FALSE when a consulted operand has not produced a
      // value within the timeout, whatever the operands compute.
      if (local == kInf) return v;  // only constants consulted
      const double deadline = local + n.timeout_s;
      if (now > deadline) return false;
      next_wake = std::min(next_wake, std::nextafter(deadline, kInf));
    }
    return v;
  }

  // --- Scanning -------------------------------------------------------------------------------

  // Evaluates rule i of f and tracks its FALSE-to-TRUE transitions (for ballistic actions).
  bool EvalRule(Frame& f, int i) {
    double oldest = kInf;
    const bool v = Eval(f, f.roots[i], oldest);
    f.values[i] = v;
    if (v && !f.prev_values[i]) f.armed[i] = 1;
    if (!v) f.armed[i] = 0;
    f.prev_values[i] = v;
    return v;
  }

  // Scans f from the top. The highest true rule's action is dealt with as soon as that rule is
  // found, then the rules below it are evaluated in the same scan (every active condition is
  // monitored): the latency from a change to the action does not grow with the rules below.
  void ScanFrame(Frame& f) {
    const Program& p = file.programs[f.program];
    const int m = static_cast<int>(p.rules.size());
    f.firing = -1;
    int i = 0;
    for (; i < m; ++i) {
      if (EvalRule(f, i)) {
        f.firing = i;
        ++i;
        break;
      }
    }
    ActOnFiringRule(f, p);
    // Acting never removes f itself (cancelling deactivates only its callees; completed calls
    // are closed after the pass), so f is still valid here.
    for (; i < m; ++i) EvalRule(f, i);
  }

  void ActOnFiringRule(Frame& f, const Program& p) {
    // Finished ballistic runs leave.
    f.ballistic.erase(std::remove_if(f.ballistic.begin(), f.ballistic.end(),
                                     [](const std::unique_ptr<Run>& r) { return r->done; }),
                      f.ballistic.end());
    const int r = f.firing;
    if (r < 0) {
      if (f.energized) {
        Cancel(f.energized.get());
        f.energized.reset();
        f.energized_rule = -1;
        dirty = true;
      }
      return;
    }
    const Rule& rule = p.rules[r];
    if (r == 0 && f.caller_run && rule.action.op == ActOp::kNil) {
      completed_frames.push_back(f.id);  // the subroutine's goal holds: the call completes
    }
    const bool ballistic = ActionSemantics(file, rule) == Semantics::kBallistic;
    if (!ballistic) {
      if (f.energized_rule != r) {
        f.energized = ReplaceAction(f, std::move(f.energized), r, false);
        f.energized_rule = r;
      } else if (f.energized && !f.watched[r].empty() && BindingsChanged(f, r, *f.energized)) {
        // The action follows its condition's outputs: restarted with their new values (what
        // both the old and the new binding run goes on, ReplaceAction). At most once per
        // Scan() call, so outputs that change on every computation cannot spin the scan: a
        // change pushed re-entrantly during the call that started the action is taken at the
        // next event.
        if (f.energized->started_call < scan_calls) {
          f.energized = ReplaceAction(f, std::move(f.energized), r, false);
        }
      } else if (f.energized && f.energized->done && f.energized->done_call < scan_calls &&
                 !HasLiveCallee(f.energized.get())) {
        f.energized = StartRule(f, r, false);  // sustained: restarted at a later scan
      }
      return;
    }
    bool start = false;
    if (f.armed[r]) {
      f.armed[r] = 0;
      start = true;
      for (const auto& b : f.ballistic) start = start && b->rule != r;
    }
    if (start) {
      auto run = ReplaceAction(f, std::move(f.energized), r, true);
      if (!run->done) f.ballistic.push_back(std::move(run));
    } else if (f.energized) {
      Cancel(f.energized.get());
      dirty = true;
    }
    f.energized.reset();
    f.energized_rule = -1;
  }

  // Drops forgotten transient processes; called where no pointer to a process is held.
  void Sweep() {
    for (const std::string& key : garbage) {
      auto it = processes.find(key);
      if (it != processes.end() && it->second->refs == 0 && !it->second->ticket) {
        processes.erase(it);
      }
    }
    garbage.clear();
  }

  void DoScan(double t) {
    if (!in_scan) Sweep();
    now = t;
    ++scan_calls;
    in_scan = true;
    int passes = 0;
    do {
      dirty = false;
      ++pass;
      ++scans;
      next_wake = kInf;
      demanded.clear();
      completed_frames.clear();
      scan_ids.clear();
      for (const auto& [id, f] : frames) scan_ids.push_back(id);
      for (int id : scan_ids) {
        auto it = frames.find(id);
        if (it != frames.end()) ScanFrame(*it->second);
      }
      for (int id : completed_frames) {
        auto it = frames.find(id);
        if (it == frames.end()) continue;
        Run* leaf = it->second->caller_run;
        if (!leaf || leaf->done) continue;  // goal holds again in a kept-active subroutine
        const bool keep = KeepsCalleeActive(leaf);
        if (!keep) Deactivate(id);
        LeafDone(leaf, keep);
      }
      for (Process* p : demanded) {
        const bool timer =
            p->kind != Registry::ConditionKind::kExternal && p->frequency_hz > 0 && !p->computing;
        if (timer) next_wake = std::min(next_wake, p->next_due);
      }
    } while (dirty && ++passes < options.max_events_per_advance);
    in_scan = false;
  }

  void Event(double t) {
    if (in_scan) {
      dirty = true;
      return;
    }
    DoScan(t);
  }
};

Interpreter::Interpreter() : impl_(std::make_unique<Impl>()) {}
Interpreter::~Interpreter() {
  if (impl_) {
    std::vector<int> ids;
    for (const auto& [id, f] : impl_->frames) ids.push_back(id);
    for (int id : ids) impl_->Deactivate(id);
  }
}

std::unique_ptr<Interpreter> Interpreter::Create(const ProgramFile& file, const Registry& registry,
                                                 std::vector<Diagnostic>* diagnostics,
                                                 const std::string& main_name, Options options) {
  std::vector<Diagnostic> local;
  std::vector<Diagnostic>& out = diagnostics ? *diagnostics : local;
  CheckReport report = CheckProgram(file);
  out.insert(out.end(), report.diagnostics.begin(), report.diagnostics.end());
  auto error = [&](Location where, const std::string& message) {
    out.push_back(Diagnostic{Diagnostic::Severity::kError, file.file, where, message});
  };
  if (!report.ok()) return nullptr;
  for (const ConditionDecl& c : file.conditions) {
    if (!registry.FindCondition(c.name)) {
      error(c.where, "condition '" + c.name + "' is not bound to a C++ function in the registry");
    }
  }
  for (const ActionDecl& a : file.actions) {
    if (!registry.FindAction(a.name)) {
      error(a.where, "action '" + a.name + "' is not bound to a C++ function in the registry");
    }
  }
  const Program* main = main_name.empty() ? file.Main() : file.FindProgram(main_name);
  if (!main) {
    error(Location{}, main_name.empty() ? "the file has no main program"
                                        : "no program named '" + main_name + "'");
  } else if (!main->params.empty()) {
    error(main->where, "program '" + main->name + "' takes parameters and cannot run as main");
  }
  for (const std::string& name : options.off_subroutines) {
    if (!file.FindProgram(name))
      error(Location{}, "no subroutine named '" + name + "' to switch off");
    else if (main && name == main->name)
      error(Location{}, "the main program '" + name + "' cannot be switched off");
  }
  if (HasErrors(out)) return nullptr;
  std::unique_ptr<Interpreter> in(new Interpreter());
  Impl& impl = *in->impl_;
  impl.file = file;
  ResolveCalls(impl.file);
  impl.registry = registry;
  impl.options = options;
  impl.off.insert(options.off_subroutines.begin(), options.off_subroutines.end());
  impl.main_name = main->name;
  impl.main_program = impl.file.ProgramIndex(main->name);
  for (const Program& p : impl.file.programs) {
    std::vector<std::set<std::string>> rules;
    for (const Rule& r : p.rules) {
      std::set<std::string> vars;
      std::vector<const ActExpr*> stack{&r.action};
      while (!stack.empty()) {
        const ActExpr* a = stack.back();
        stack.pop_back();
        for (const Arg& arg : a->args) {
          if (arg.kind == Arg::Kind::kVariable) vars.insert(arg.text);
        }
        for (const ActExpr& k : a->children) stack.push_back(&k);
      }
      rules.push_back(std::move(vars));
    }
    impl.action_vars.push_back(std::move(rules));
  }
  return in;
}

void Interpreter::Start(double now) {
  Impl& m = *impl_;
  if (m.started) Stop(now);
  m.started = true;
  m.now = now;
  m.NewFrame(m.main_program, {}, -1, nullptr, 0);
  m.DoScan(now);
}

void Interpreter::Stop(double now) {
  Impl& m = *impl_;
  m.now = now;
  std::vector<int> ids;
  for (const auto& [id, f] : m.frames) ids.push_back(id);
  for (int id : ids) m.Deactivate(id);
  m.started = false;
  m.next_wake = kInf;
}

void Interpreter::Advance(double now) {
  if (!impl_->started) return;
  if (now >= impl_->next_wake) impl_->DoScan(now);
}

void Interpreter::Scan(double now) {
  if (impl_->started && !impl_->in_scan) impl_->DoScan(now);
}

double Interpreter::NextWakeTime() const { return impl_->started ? impl_->next_wake : kInf; }

bool Interpreter::SetCondition(const std::string& name, bool value, double now,
                               std::vector<Value> outputs, std::vector<Value> inputs) {
  Impl& m = *impl_;
  const ConditionDecl* d = m.file.FindCondition(name);
  if (!d) return false;
  const auto* b = m.registry.FindCondition(name);
  if (!b || b->kind != Registry::ConditionKind::kExternal) return false;
  if (static_cast<int>(inputs.size()) != d->NumInputs()) return false;
  Process* p = m.GetProcess(d, std::move(inputs));
  outputs.resize(p->outputs.size());
  const bool changed = !p->has_value || p->value != value || p->outputs != outputs;
  p->value = value;
  p->has_value = true;
  p->outputs = std::move(outputs);
  p->last_update = now;
  if (m.started && (changed || p->refs > 0)) m.Event(now);
  return true;
}

bool Interpreter::CompleteCondition(Ticket ticket, bool value, double now,
                                    std::vector<Value> outputs) {
  Impl& m = *impl_;
  auto it = m.condition_tickets.find(ticket);
  if (it == m.condition_tickets.end()) return false;
  Process* p = it->second;
  m.condition_tickets.erase(it);
  outputs.resize(p->outputs.size());
  p->ticket = 0;
  p->computing = false;
  p->value = value;
  p->has_value = true;
  p->outputs = std::move(outputs);
  p->last_update = now;
  const double f = p->decl->frequency_hz;
  p->next_due = f > 0 ? now + 1.0 / f : now;
  m.Event(now);
  return true;
}

bool Interpreter::CompleteAction(Ticket ticket, bool /*success*/, double now) {
  Impl& m = *impl_;
  auto it = m.action_tickets.find(ticket);
  if (it == m.action_tickets.end()) return false;
  Run* r = it->second;
  m.action_tickets.erase(it);
  m.now = now;
  m.LeafDone(r);
  m.Event(now);
  return true;
}

InterpreterState Interpreter::State() const {
  const Impl& m = *impl_;
  InterpreterState s;
  s.main = m.main_name;
  s.now = m.now;
  s.scans = m.scans;
  std::map<int, int> index;
  for (const auto& [id, f] : m.frames) {
    FrameState fs;
    const Program& p = m.file.programs[f->program];
    fs.program = p.name;
    for (const Value& v : f->args) fs.args.push_back(ValueToString(v));
    fs.depth = f->depth;
    auto ci = index.find(f->caller_frame);
    fs.caller = ci == index.end() ? -1 : ci->second;
    fs.rule_values.assign(f->values.begin(), f->values.end());
    fs.firing_rule = f->firing;
    fs.action_running =
        f->firing >= 0 && f->energized_rule == f->firing && f->energized && !f->energized->done;
    for (const auto& b : f->ballistic) {
      if (b->done) continue;
      ++fs.ballistic_running;
      if (b->rule == f->firing) fs.action_running = true;
    }
    index[id] = static_cast<int>(s.frames.size());
    s.frames.push_back(std::move(fs));
  }
  for (const auto& [key, p] : m.processes) {
    ProcessState ps;
    ps.name = key;
    ps.value =
        p->has_value && p->value && !(p->computing && p->decl->semantics == Semantics::kBallistic);
    ps.active = p->refs > 0;
    ps.computing = p->computing;
    ps.semantics = p->decl->semantics;
    ps.frequency_hz = p->decl->frequency_hz;
    ps.last_update = p->last_update;
    int out = 0;
    for (const ConditionParam& cp : p->decl->params) {
      if (cp.is_output) ps.outputs.emplace_back(cp.name, ValueToString(p->outputs[out++]));
    }
    s.processes.push_back(std::move(ps));
  }
  return s;
}

uint64_t Interpreter::scans() const { return impl_->scans; }
const ProgramFile& Interpreter::program() const { return impl_->file; }
const std::string& Interpreter::main_name() const { return impl_->main_name; }

}  // namespace spott_tr_plus
