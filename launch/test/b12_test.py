#!/usr/bin/env python3
# SPOTT on the B-12 (issue 19): the same TR+ navigation program as on the Nomad 200, on a robot
# whose only sensor is a ring of 12 sonars, with the bumper, infrared and QUADRIS subroutines
# switched off (config/robots/b12.yaml), as the paper ran it on its second platform. The
# scenario scenarios/cim_office_b12.yaml (the main demo's first two tasks on cim_office, markov
# localization on the 12 sonars) runs as ./spott run runs it; the test checks on the ground truth
# that every task was reached and the body never touched anything (the B-12 has no bumper: the
# simulator's /sim/contact), and on the controller's published state that the switched-off
# subroutines were never entered while the sonar's was. Python because the runner's parts are
# command-line programs.
import json
import os
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest
from workspace_tools import run_scenario
from spott_msgs.msg import TRProgramState

PKG = 'spott_launch'
SCENARIO = 'cim_office_b12.yaml'
OFF = {'BUMPER_CHECK', 'INFRARED_CHECK', 'MAP_OBJECTS_WITH_INFRARED', 'MAP_OBJECTS_WITH_QUADRIS',
       'CONTROL_THE_PTU'}
B12_RADIUS_M = 0.1525  # robot_sim/urdf/b12.urdf


class B12(unittest.TestCase):
    def test_spotts_program_on_the_b12_reaches_every_task_without_contact(self):
        entered = set()
        rospy.init_node('b12_test', anonymous=True)
        rospy.Subscriber('/tr_plus_controller/state', TRProgramState,
                         lambda m: entered.update(c.split('(')[0] for c in m.call_chain),
                         queue_size=50)
        scenario = os.path.join(rospkg.RosPack().get_path(PKG), 'scenarios', SCENARIO)
        with tempfile.TemporaryDirectory() as d:
            args, r = run_scenario(self, scenario, d, timeout_s=330)
        self.assertIn('robot:=b12', args)
        self.assertIn('controller:=tr_plus', args)
        legs = json.dumps([{k: leg[k] for k in ('task', 'outcome', 'min_wall_distance_m')}
                           for leg in r['legs']], indent=1)
        self.assertTrue(r['ok'], r.get('failure'))
        self.assertEqual(len(r['legs']), 2, legs)
        # Reached on the ground truth, and the body never touched a wall or object.
        self.assertEqual(r['outcome'], 'succeeded', legs)
        self.assertEqual(r['totals']['body_contacts'], 0, legs)
        self.assertGreater(r['totals']['min_wall_distance_m'], B12_RADIUS_M, legs)
        # The same program: the main program and the sonar's subroutines ran, the switched-off
        # ones never did (the Nomad's run enters BUMPER_CHECK and CONTROL_THE_PTU at once).
        self.assertIn('SPOTT', entered)
        self.assertIn('MAP_OBJECTS_WITH_SONAR', entered)
        self.assertIn('LOCALIZE_THE_ROBOT', entered)
        self.assertEqual(entered & OFF, set(), sorted(entered))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'b12_test', B12, sys.argv)
