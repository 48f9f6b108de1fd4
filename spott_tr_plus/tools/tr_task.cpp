// tr_task "COMMAND" [TIMEOUT_S]: gives the TR+ controller a task command on /task
// (spott_msgs/Task), prints the feedback as it changes (state, firing rule, distance remaining)
// and the result (outcome, interpretation, the TR trace, the features added). Exits 0 when the
// task succeeded. Ctrl-C cancels the task (the robot stops).
#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>
#include <spott_msgs/TaskAction.h>

#include <cmath>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  ros::init(argc, argv, "tr_task", ros::init_options::AnonymousName);
  if (argc < 2) {
    std::fprintf(stderr, "usage: tr_task \"go in room(lab)\" [TIMEOUT_S]\n");
    return 2;
  }
  const double timeout = argc > 2 ? std::atof(argv[2]) : 600.0;
  actionlib::SimpleActionClient<spott_msgs::TaskAction> client("task", true);
  if (!client.waitForServer(ros::Duration(30.0))) {
    std::fprintf(stderr, "tr_task: /task is not offered (is tr_plus_controller running?)\n");
    return 1;
  }
  spott_msgs::TaskGoal goal;
  goal.command = argv[1];
  std::string last;
  client.sendGoal(goal, actionlib::SimpleActionClient<spott_msgs::TaskAction>::SimpleDoneCallback(),
                  actionlib::SimpleActionClient<spott_msgs::TaskAction>::SimpleActiveCallback(),
                  [&last](const spott_msgs::TaskFeedbackConstPtr& fb) {
                    const std::string line = fb->state + " | " + fb->firing_rule;
                    if (line == last) return;
                    last = line;
                    std::printf("[%8.2f] %s | %s m to go\n", ros::Time::now().toSec(), line.c_str(),
                                std::isfinite(fb->distance_remaining)
                                    ? std::to_string(fb->distance_remaining).c_str()
                                    : "?");
                    std::fflush(stdout);
                  });
  if (!client.waitForResult(ros::Duration(timeout))) {
    client.cancelGoal();
    client.waitForResult(ros::Duration(5.0));
  }
  const auto r = client.getResult();
  if (!r) {
    std::fprintf(stderr, "tr_task: no result (%s)\n", client.getState().toString().c_str());
    return 1;
  }
  std::printf("outcome: %s%s%s\n", r->outcome.c_str(), r->message.empty() ? "" : ": ",
              r->message.c_str());
  if (!r->interpretation.empty()) std::printf("interpretation: %s\n", r->interpretation.c_str());
  for (const std::string& rule : r->trace) std::printf("  fired: %s\n", rule.c_str());
  std::printf("features in the map added by the controller: %zu\n", r->features_added.size());
  return r->success ? 0 : 1;
}
