// The messages exchanged by the controller's modules, recorded in order (Fig. 5 of the paper:
// executive EM, surveillance manager SM, sensor surveillance managers US-SSM ..., the modules
// PILOT ...). Tests assert the order; a node may publish them for debugging.
#pragma once

#include <cstddef>
#include <deque>
#include <string>

namespace rpl_executive::noreils_chatila {

struct Message {
  /// What the message is, with Fig. 5's numbers where the figure has one.
  enum class Kind {
    kOperator,       ///< (1) EM -> module: an execution operator
    kMonitor,        ///< (2) EM -> SM: a surveillance monitor
    kMonitorId,      ///< (3) SM -> EM: its identifier <n>
    kControlStored,  ///< EM: control action memorized under <n>
    kCondition,      ///< (4) SM -> SSM: the left member labelled <n>
    kConditionTrue,  ///< (5) SSM -> SM: condition <n> true
    kReflex,         ///< (6-1) SM -> module: the reflex action
    kFired,          ///< (6-2) SM -> EM: monitor <n> fired
    kReport,         ///< (7) module -> EM: the operator's end (interrupted, completed, failed)
    kDestroy,        ///< EM -> SM: monitor <n> destroyed
    kControlAction,  ///< EM: control action of <n> run
    kHalt,           ///< EM -> module: halt (NEXT, FAIL, ENV no longer holds)
    kKill,           ///< EM -> SM: monitor <n> killed with its action (not fired)
    kEnv,            ///< EM: a task's execution environment no longer holds
    kDiagnosis,      ///< EM -> DM: diagnostic step
    kMission,        ///< EM: mission started / refused / succeeded / failed
    kNote,           ///< anything else worth a line
  };
  double time_s = 0.0;
  Kind kind = Kind::kNote;
  std::string from;
  std::string to;
  int monitor = 0;  ///< the monitor's identifier, 0 when none
  std::string text;
  std::string ToString() const;
};

const char* KindName(Message::Kind kind);

/// The last `capacity` messages (0: recording off, as benchmarks run).
class MessageLog {
 public:
  explicit MessageLog(size_t capacity = 100000) : capacity_(capacity) {}
  void Add(double time_s, Message::Kind kind, std::string from, std::string to, int monitor,
           std::string text);
  const std::deque<Message>& messages() const { return messages_; }
  void Clear() { messages_.clear(); }
  void set_capacity(size_t capacity);
  size_t capacity() const { return capacity_; }
  bool enabled() const { return capacity_ > 0; }
  std::string ToString() const;

 private:
  size_t capacity_;
  std::deque<Message> messages_;
};

}  // namespace rpl_executive::noreils_chatila
