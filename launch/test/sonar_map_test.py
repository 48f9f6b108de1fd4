#!/usr/bin/env python3
# SPOTT's sonar map of cim_office's hallway (issue 19: "a sonar map of cim_office's hall whose
# segments match the walls"): scenarios/cim_office_hall_sonar_map.yaml run whole (the map
# database empty, QUADRIS's mapping off, the robot driving the hallway slowly), its bag scored by
# scripts/sonar_map_score.py against the world's walls. The target is precision and
# recall above 0.9; with the dense scan, driving the hallway end to end, the stack reaches 0.99
# and 0.91 (spott_tr_plus README, "Sonar map"; per run precision 0.93-1.0, recall 0.905-0.915,
# strict 0.87-1.0): the test holds precision >= 0.9, no part in an open doorway for 0.75 of the
# segments, and recall >= 0.88, so that a regression shows. Not in CI
# (about 80 s of its budget): `rostest spott_launch sonar_map.test`.
import math
import os
import sys
import tempfile
import unittest

import rospkg
import rostest
import yaml
from workspace_tools import run_scenario

PKG = 'spott_launch'
SCENARIO = 'cim_office_hall_sonar_map.yaml'
sys.path.insert(0, os.path.join(rospkg.RosPack().get_path(PKG), 'scripts'))
import sonar_map_score  # noqa: E402


class Args:
    sensor = 'sonar'
    distance = 0.10
    angle = 5.0
    slack = 0.05


class SonarMap(unittest.TestCase):
    def test_the_hallways_sonar_segments_lie_on_its_walls(self):
        path = rospkg.RosPack().get_path(PKG)
        scenario = os.path.join(path, 'scenarios', SCENARIO)
        worlds = rospkg.RosPack().get_path('spott_worlds')
        with open(os.path.join(worlds, 'worlds', 'cim_office.yaml')) as f:
            world = yaml.safe_load(f)
        samples = sonar_map_score.surfaces(world)
        grid = sonar_map_score.Grid(samples)
        hall = sonar_map_score.bounding_walls(samples, world['rooms'], {'hall_w', 'hall_e'})
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, 'run.bag')
            _, r = run_scenario(self, scenario, d, extra_args=['bag:=' + bag], timeout_s=400)
            s = sonar_map_score.score(bag, world, Args, grid, hall)
        self.assertTrue(r['ok'], r.get('failure'))
        self.assertEqual(r['legs'][0]['body_contacts'], 0)
        shown = str(s)
        self.assertGreaterEqual(s['segments'], 10, shown)
        self.assertGreaterEqual(s['on_line'] / s['segments'], 0.9, shown)
        self.assertGreaterEqual(s['matched'] / s['segments'], 0.75, shown)
        self.assertGreaterEqual(s['covered_m'] / s['wall_m'], 0.88, shown)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'sonar_map_test', SonarMap, sys.argv)
