#include "spott_tr_plus/registry.h"

#include <stdexcept>

namespace spott_tr_plus {

Registry& Registry::Condition(const std::string& name, SyncConditionFn fn) {
  if (!fn) throw std::invalid_argument("Registry::Condition: empty function for " + name);
  conditions_[name] = ConditionBinding{ConditionKind::kSync, std::move(fn), nullptr};
  return *this;
}

Registry& Registry::AsyncCondition(const std::string& name, AsyncConditionFn fn) {
  if (!fn) throw std::invalid_argument("Registry::AsyncCondition: empty function for " + name);
  conditions_[name] = ConditionBinding{ConditionKind::kAsync, nullptr, std::move(fn)};
  return *this;
}

Registry& Registry::ExternalCondition(const std::string& name) {
  conditions_[name] = ConditionBinding{ConditionKind::kExternal, nullptr, nullptr};
  return *this;
}

Registry& Registry::Action(const std::string& name, ActionStart start, ActionStop stop) {
  if (!start) throw std::invalid_argument("Registry::Action: empty start function for " + name);
  actions_[name] = ActionBinding{std::move(start), std::move(stop), nullptr};
  return *this;
}

Registry& Registry::InstantAction(const std::string& name, InstantFn fn) {
  if (!fn) throw std::invalid_argument("Registry::InstantAction: empty function for " + name);
  actions_[name] = ActionBinding{nullptr, nullptr, std::move(fn)};
  return *this;
}

const Registry::ConditionBinding* Registry::FindCondition(const std::string& name) const {
  auto it = conditions_.find(name);
  return it == conditions_.end() ? nullptr : &it->second;
}

const Registry::ActionBinding* Registry::FindAction(const std::string& name) const {
  auto it = actions_.find(name);
  return it == actions_.end() ? nullptr : &it->second;
}

}  // namespace spott_tr_plus
