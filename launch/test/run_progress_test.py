#!/usr/bin/env python3
# ./spott run's live line (scripts/run_progress.py): what it counts from the messages it hears.
# No stack: the messages are made here.
import math
import os
import sys
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from spott_msgs.msg import (BumperRing, NavigateActionFeedback, NavigateActionGoal,
                            TaskActionFeedback, TaskActionGoal)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import run_progress  # noqa: E402

PKG = 'spott_launch'


def truth(x, y, t):
    m = Odometry()
    m.header.stamp = rospy.Time.from_sec(t)
    m.pose.pose.position.x, m.pose.pose.position.y = x, y
    return m


def bumper(*pressed):
    m = BumperRing()
    m.pressed = list(pressed)
    return m


class RunProgress(unittest.TestCase):
    def test_distance_is_the_ground_truth_path_and_time_its_stamp(self):
        p = run_progress.Progress()
        for x, y, t in [(0, 0, 1.0), (3, 4, 2.0), (3, 0, 3.5)]:
            p.on_truth(truth(x, y, t))
        self.assertAlmostEqual(p.driven_m, 9.0)
        self.assertAlmostEqual(p.sim_s, 3.5)
        self.assertTrue(p.line().startswith('t    3.5 s |   9.0 m'), p.line())

    def test_a_contact_is_counted_once_while_pressed(self):
        p = run_progress.Progress()
        for m in [bumper(False, True), bumper(True, True), bumper(False, False), bumper(True)]:
            p.on_bumper(m)
        self.assertEqual(p.contacts, 2)
        self.assertIn('2 contacts', p.line())

    def test_the_task_names_the_line_and_its_own_navigate_goals_do_not(self):
        p = run_progress.Progress()
        self.assertIn('waiting for the first task', p.line())
        g = TaskActionGoal()
        g.goal.command = 'go in room(lab)'
        p.on_task_goal(g)
        n = NavigateActionGoal()
        n.goal.target.pose.position.x, n.goal.target.pose.position.y = 20.0, 15.0
        p.on_navigate_goal(n)  # the controller's Navigate for the task
        f = TaskActionFeedback()
        f.feedback.state, f.feedback.distance_remaining = 'driving', 4.56
        p.on_task_feedback(f)
        self.assertTrue(p.line().endswith('go in room(lab): driving, 4.6 m to go'), p.line())

    def test_navigate_legs_show_their_target_and_state(self):
        p = run_progress.Progress()
        n = NavigateActionGoal()
        n.goal.target.pose.position.x, n.goal.target.pose.position.y = 2.5, 7.0
        p.on_navigate_goal(n)
        f = NavigateActionFeedback()
        f.feedback.state, f.feedback.distance_remaining = 0, math.nan
        p.on_navigate_feedback(f)
        self.assertTrue(p.line().endswith('navigate to (2.5, 7.0): planning'), p.line())
        f.feedback.state, f.feedback.distance_remaining = 1, 3.0
        p.on_navigate_feedback(f)
        self.assertTrue(p.line().endswith('navigate to (2.5, 7.0): driving, 3.0 m to go'))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'run_progress_test', RunProgress)
