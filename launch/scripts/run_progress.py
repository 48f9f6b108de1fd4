#!/usr/bin/env python3
# The live progress line of ./spott run (issue 20): simulated time, distance driven (ground
# truth), bumper contacts, and the current task or Navigate goal with its state and the distance
# left, on one line of stderr rewritten in place (a terminal) or printed every 15 s (a log).
# It only listens; it ends when the master goes away. Usage (the run's ROS_MASTER_URI set):
#   launch/scripts/run_progress.py
import math
import sys
import time

STATES = {0: 'planning', 1: 'driving', 2: 'recovering'}  # spott_msgs/NavigateFeedback


def format_line(sim_s, driven_m, contacts, what, state, remaining_m):
    """One progress line; `what` the task command or goal, `remaining_m` NaN when unknown."""
    parts = ['t %6.1f s' % sim_s, '%5.1f m' % driven_m]
    if contacts:
        parts.append('%d contact%s' % (contacts, '' if contacts == 1 else 's'))
    if what:
        task = what if len(what) <= 40 else what[:37] + '...'
        detail = state or 'sent'
        if remaining_m is not None and math.isfinite(remaining_m):
            detail += ', %.1f m to go' % remaining_m
        parts.append('%s: %s' % (task, detail))
    else:
        parts.append('waiting for the first task')
    return ' | '.join(parts)


class Progress:
    def __init__(self):
        self.sim_s = 0.0
        self.driven_m = 0.0
        self.last_xy = None
        self.contacts = 0
        self.pressed = False
        self.what = ''
        self.state = ''
        self.remaining_m = float('nan')

    def on_truth(self, msg):
        p = msg.pose.pose.position
        if self.last_xy is not None:
            self.driven_m += math.hypot(p.x - self.last_xy[0], p.y - self.last_xy[1])
        self.last_xy = (p.x, p.y)
        self.sim_s = msg.header.stamp.to_sec()

    def on_bumper(self, msg):
        pressed = any(msg.pressed)
        if pressed and not self.pressed:
            self.contacts += 1
        self.pressed = pressed

    def on_task_goal(self, msg):
        self.what, self.state, self.remaining_m = msg.goal.command, '', float('nan')

    def on_task_feedback(self, msg):
        self.state = msg.feedback.state
        self.remaining_m = msg.feedback.distance_remaining

    def on_navigate_goal(self, msg):
        if self.what and not self.what.startswith('navigate to'):
            return  # the task's own Navigate: the task names it better
        p = msg.goal.target.pose.position
        self.what, self.state, self.remaining_m = 'navigate to (%.1f, %.1f)' % (p.x, p.y), '', float('nan')

    def on_navigate_feedback(self, msg):
        if self.what.startswith('navigate to'):
            self.state = STATES.get(msg.feedback.state, str(msg.feedback.state))
            self.remaining_m = msg.feedback.distance_remaining

    def line(self):
        return format_line(self.sim_s, self.driven_m, self.contacts, self.what, self.state,
                           self.remaining_m)


def main():
    import rosgraph
    import rospy
    from nav_msgs.msg import Odometry
    from spott_msgs.msg import (BumperRing, NavigateActionFeedback, NavigateActionGoal,
                                TaskActionFeedback, TaskActionGoal)

    master = rosgraph.Master('/run_progress')
    while not master.is_online():  # the run's roslaunch starts it
        time.sleep(0.5)
    rospy.init_node('run_progress', anonymous=True, disable_signals=True)
    p = Progress()
    rospy.Subscriber('/sim/ground_truth', Odometry, p.on_truth, queue_size=50)
    rospy.Subscriber('/bumper', BumperRing, p.on_bumper, queue_size=10)
    rospy.Subscriber('/task/goal', TaskActionGoal, p.on_task_goal, queue_size=5)
    rospy.Subscriber('/task/feedback', TaskActionFeedback, p.on_task_feedback, queue_size=5)
    rospy.Subscriber('/harmonic_planner/navigate/goal', NavigateActionGoal, p.on_navigate_goal,
                     queue_size=5)
    rospy.Subscriber('/harmonic_planner/navigate/feedback', NavigateActionFeedback,
                     p.on_navigate_feedback, queue_size=5)
    tty = sys.stderr.isatty()
    last_print = 0.0
    while master.is_online() and not rospy.is_shutdown():
        time.sleep(0.5)
        if tty:
            sys.stderr.write('\r\033[K' + p.line())
            sys.stderr.flush()
        elif time.time() - last_print >= 15.0:
            last_print = time.time()
            sys.stderr.write(p.line() + '\n')
    if tty:
        sys.stderr.write('\n')
    rospy.signal_shutdown('the run ended')


if __name__ == '__main__':
    main()
