#include "rpl_executive/noreils_chatila/messages.h"

#include <cstdio>

namespace rpl_executive::noreils_chatila {

const char* KindName(Message::Kind kind) {
  switch (kind) {
    case Message::Kind::kOperator:
      return "operator (1)";
    case Message::Kind::kMonitor:
      return "monitor (2)";
    case Message::Kind::kMonitorId:
      return "id (3)";
    case Message::Kind::kControlStored:
      return "control stored";
    case Message::Kind::kCondition:
      return "condition (4)";
    case Message::Kind::kConditionTrue:
      return "true (5)";
    case Message::Kind::kReflex:
      return "reflex (6-1)";
    case Message::Kind::kFired:
      return "fired (6-2)";
    case Message::Kind::kReport:
      return "report (7)";
    case Message::Kind::kDestroy:
      return "destroy";
    case Message::Kind::kControlAction:
      return "control action";
    case Message::Kind::kHalt:
      return "halt";
    case Message::Kind::kKill:
      return "kill";
    case Message::Kind::kEnv:
      return "env";
    case Message::Kind::kDiagnosis:
      return "diagnosis";
    case Message::Kind::kMission:
      return "mission";
    case Message::Kind::kNote:
      return "note";
  }
  return "?";
}

std::string Message::ToString() const {
  char head[64];
  std::snprintf(head, sizeof head, "%9.3f ", time_s);
  std::string out = head;
  out += from;
  if (!to.empty()) out += " -> " + to;
  out += std::string(" [") + KindName(kind) + "]";
  if (monitor != 0) out += " <n" + std::to_string(monitor) + ">";
  if (!text.empty()) out += " " + text;
  return out;
}

void MessageLog::Add(double time_s, Message::Kind kind, std::string from, std::string to,
                     int monitor, std::string text) {
  if (capacity_ == 0) return;
  Message m;
  m.time_s = time_s;
  m.kind = kind;
  m.from = std::move(from);
  m.to = std::move(to);
  m.monitor = monitor;
  m.text = std::move(text);
  messages_.push_back(std::move(m));
  while (messages_.size() > capacity_) messages_.pop_front();
}

void MessageLog::set_capacity(size_t capacity) {
  capacity_ = capacity;
  while (messages_.size() > capacity_) messages_.pop_front();
}

std::string MessageLog::ToString() const {
  std::string out;
  for (const Message& m : messages_) out += m.ToString() + "\n";
  return out;
}

}  // namespace rpl_executive::noreils_chatila
