#!/usr/bin/env python3
# GO across cim_office without a map (issue 19): scenarios/spott_go_across_without_map.yaml run
# whole (the map database empty, dead reckoning, from the hallway's west end to the lab). Before
# the harmonic planner explored, the robot ended UNREACHABLE in office 201's doorway pocket. The
# test checks that the planner explored (its Navigate feedback said so), that the controller
# reached the task, that on the ground truth the robot ended in the lab within 1.5 m of the goal
# (dead reckoning's drift: 0.03-1.32 m in 18 runs on 2026-12-05; the scenario now localizes on
# the sensed map, 7 of 10 within 0.25 m on 2026-12-07, the misses from drift along the lab's
# diagonal) and that nothing was touched.
# Python because the runner's parts are command-line programs.
import json
import os
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest
from workspace_tools import run_scenario
from spott_msgs.msg import NavigateActionFeedback

PKG = 'spott_launch'
SCENARIO = 'spott_go_across_without_map.yaml'
DRIFT_M = 1.5


class GoWithoutMap(unittest.TestCase):
    def test_go_across_the_building_without_a_map_arrives(self):
        notes = set()
        rospy.init_node('go_without_map_test', anonymous=True)
        rospy.Subscriber('/harmonic_planner/navigate/feedback', NavigateActionFeedback,
                         lambda m: notes.add(m.feedback.note.split(':')[0]), queue_size=50)
        scenario = os.path.join(rospkg.RosPack().get_path(PKG), 'scenarios', SCENARIO)
        with tempfile.TemporaryDirectory() as d:
            args, r = run_scenario(self, scenario, d, timeout_s=600)
        self.assertIn('a_priori_map:=false', args)
        self.assertTrue(r['ok'], r.get('failure'))
        self.assertEqual(len(r['legs']), 1)
        leg = r['legs'][0]
        shown = json.dumps({k: leg[k] for k in ('task', 'outcome', 'task_outcome',
                                                'final_error_m', 'final_position',
                                                'min_wall_distance_m', 'body_contacts')})
        self.assertIn('exploring', notes, shown)
        self.assertEqual(leg['task_outcome'], 'reached', shown)
        self.assertLess(leg['final_error_m'], DRIFT_M, shown)
        self.assertGreater(leg['final_position'][1], 13.0, shown)  # in the lab, not the hallway
        self.assertEqual(leg['body_contacts'], 0, shown)
        self.assertEqual(leg['bumper_hits'], 0, shown)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'go_without_map_test', GoWithoutMap, sys.argv)
