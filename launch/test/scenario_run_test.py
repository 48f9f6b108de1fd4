#!/usr/bin/env python3
# A scenario as `./spott run` runs it: scenario_tool checks the file and writes the launch
# arguments, demo_report's parameters and robot_sim's fault schedule; demo.launch runs the whole
# stack with them on this test's master, records a bag and writes the JSON report. The test
# checks that the run was the scenario's (world, goals, each fault at its time in its leg), that
# the JSON agrees with itself and with the bag, that bag_report recomputes the same report from
# the bag alone, and that a bad scenario is refused with its line and column. Python because the runner's parts are command-line programs.
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospkg
import rostest
from workspace_tools import find_tool, run_scenario

PKG = 'spott_launch'
SCENARIO = 'hilare_sonar_dropout.yaml'
PLOTS = os.path.join(rospkg.RosPack().get_path(PKG), 'scripts', 'run_plots.py')


class ScenarioRun(unittest.TestCase):
    def test_a_bad_scenario_is_refused_with_its_line_and_column(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, 'bad.yaml')
            with open(path, 'w') as f:
                f.write('world: hilare_room\ngoals: [zone_exit]\nfaults:\n'
                        '  - {time: 5, kind: sensor, sensor: sonar/1, fault: melt}\n')
            out = subprocess.run([find_tool('scenario_tool'), path, '--out', d],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=60)
            self.assertEqual(out.returncode, 1, out.stdout)
            self.assertIn(path + ':4:', out.stdout)
            self.assertIn('melt', out.stdout)
            self.assertFalse(os.path.exists(os.path.join(d, 'launch_args')))

    def test_the_run_is_the_scenarios_and_its_report_and_bag_agree(self):
        scenario = os.path.join(rospkg.RosPack().get_path(PKG), 'scenarios', SCENARIO)
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, 'run.bag')
            args, r = run_scenario(self, scenario, d, ['bag:=' + bag])
            self.assertIn('world:=hilare_room', args)
            self.assertIn('controller:=none', args)
            self.assertTrue(r['ok'], r.get('failure'))
            self.assertEqual(r['world'], 'hilare_room')
            self.assertEqual(r['scenario'], scenario)
            self.assertEqual([leg['goal'] for leg in r['legs']],
                             ['wall_follow_start', 'zone_exit', 'corridor_north'])
            # Each scheduled fault happened at its simulated time, in the leg then running.
            self.assertEqual(len(r['faults']), 3, r['faults'])
            for fault in r['faults']:
                self.assertTrue(fault['applied'], fault)
                self.assertAlmostEqual(fault['sim_time_s'], 25.0, delta=0.1)
                self.assertIn('dropout for 20 s', fault['what'])
                leg = r['legs'][fault['during_leg']]
                self.assertLessEqual(leg['start_sim_s'], fault['sim_time_s'])
            # The outcome is the legs' (ground truth, no contact), and HILARE makes it.
            reached = all(leg['reached'] for leg in r['legs'])
            contacts = sum(leg['bumper_hits'] + leg['body_contacts'] for leg in r['legs'])
            self.assertEqual(r['outcome'] == 'succeeded', reached and contacts == 0)
            self.assertEqual(r['outcome'], 'succeeded', json.dumps(r['legs'], indent=1)[-2000:])
            # The bag holds the run: the faults as they happened and the ground truth, which
            # ends where the report says the last leg ended.
            self.assertTrue(os.path.exists(bag), 'the run recorded no bag')
            with rosbag.Bag(bag) as b:
                faults = [m for _, m, _ in b.read_messages(topics=['/sim/faults'])]
                truth = [m for _, m, _ in b.read_messages(topics=['/sim/ground_truth'])]
            self.assertEqual(len(faults), 3)
            self.assertEqual(faults[0].status[0].hardware_id, 'sensor')
            self.assertGreater(len(truth), 100)
            last = truth[-1].pose.pose.position
            end = r['legs'][-1]['final_position']
            self.assertLess(((last.x - end[0]) ** 2 + (last.y - end[1]) ** 2) ** 0.5, 0.3)
            # The report recomputed from the bag alone gives the live run's figures: the same
            # legs and verdicts, the same faults, and each figure within what a message the
            # live subscriber or the recorder dropped could change.
            replayed = os.path.join(d, 'bag.json')
            out = subprocess.run([find_tool('bag_report'), bag, '--json', replayed],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=120)
            self.assertEqual(out.returncode, 0, out.stdout[-2000:])
            with open(replayed) as f:
                b = json.load(f)
            legs = lambda j: [(l['goal'], l['start_sim_s'], l['sim_time_s']) for l in j['legs']]
            self.assertEqual(len(b['legs']), len(r['legs']), '%s\n%s' % (legs(b), legs(r)))
            self.assertEqual(b['outcome'], r['outcome'])
            self.assertEqual(b['faults'], r['faults'], '%s\n%s' % (legs(b), legs(r)))
            for live, bag_leg in zip(r['legs'], b['legs']):
                name = live['goal']
                for key in ('goal', 'reached', 'outcome', 'navigate_outcome', 'bumper_hits',
                            'body_contacts', 'lost_reports', 'recoveries'):
                    self.assertEqual(bag_leg[key], live[key], '%s: %s' % (name, key))
                self.assertAlmostEqual(bag_leg['start_sim_s'], live['start_sim_s'], delta=0.05)
                self.assertAlmostEqual(bag_leg['sim_time_s'], live['sim_time_s'], delta=0.1)
                self.assertAlmostEqual(bag_leg['path_length_m'], live['path_length_m'],
                                       delta=0.01 * live['path_length_m'] + 0.02,
                                       msg=name + ': path')
                self.assertAlmostEqual(bag_leg['min_wall_distance_m'],
                                       live['min_wall_distance_m'], delta=0.01,
                                       msg=name + ': clearance')
                for a, c in zip(bag_leg['final_position'], live['final_position']):
                    self.assertAlmostEqual(a, c, delta=0.01, msg=name + ': final position')
                bl, ll = bag_leg['localization'], live['localization']
                self.assertAlmostEqual(bl['estimates'], ll['estimates'],
                                       delta=0.02 * ll['estimates'] + 1, msg=name + ': estimates')
                self.assertAlmostEqual(bl['mean_position_error_m'], ll['mean_position_error_m'],
                                       delta=0.005, msg=name + ': mean error')
                self.assertAlmostEqual(bl['max_position_error_m'], ll['max_position_error_m'],
                                       delta=0.01, msg=name + ': max error')
            # The plots ./spott run draws from the bag show the run the report describes.
            plots = os.path.join(d, 'plots')
            out = subprocess.run([sys.executable, PLOTS, bag, plots], stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True, timeout=120)
            self.assertEqual(out.returncode, 0, out.stdout[-2000:])
            for png in ('path.png', 'certainty.png', 'speed.png'):
                with open(os.path.join(plots, png), 'rb') as f:
                    self.assertEqual(f.read(8), b'\x89PNG\r\n\x1a\n', png)
            with open(os.path.join(plots, 'plots.json')) as f:
                p = json.load(f)
            legs_path = sum(leg['path_length_m'] for leg in r['legs'])
            self.assertGreaterEqual(p['path_length_m'], legs_path - 0.05)
            self.assertLess(p['path_length_m'], legs_path + 0.02 * legs_path + 0.5)
            self.assertAlmostEqual(p['max_position_error_m'], r['totals']['max_position_error_m'],
                                   delta=0.01)
            self.assertEqual(len(p['legs']), len(r['legs']))
            for drawn, leg in zip(p['legs'], r['legs']):
                for a, c in zip(drawn['target'], leg['target'][:2]):
                    self.assertAlmostEqual(a, c, delta=0.01, msg=leg['goal'])
            self.assertEqual(p['contact_samples'] > 0, r['totals']['body_contacts'] > 0)

    def test_a_mission_scenario_runs_as_the_paper_says_and_its_bag_judges_the_same(self):
        # Noreils and Chatila's Example 2 with an obstacle in the zone: rpl_executive runs the
        # shipped mission; the run counts only if the mission FAILs by the static monitor after
        # the zone's, as the paper says, with nothing touched.
        scenario = os.path.join(rospkg.RosPack().get_path(PKG), 'scenarios',
                                'hilare_example2_obstacle_in_zone.yaml')
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, 'run.bag')
            args, r = run_scenario(self, scenario, d, ['bag:=' + bag])
            self.assertIn('executive:=rpl', args)
            self.assertIn('controller:=none', args)
            self.assertTrue(r['by_mission'])
            self.assertEqual(len(r['legs']), 1)
            leg = r['legs'][0]
            self.assertEqual(leg['mission'], 'example2_zone_surveillance')
            self.assertEqual(leg['mission_outcome'], 'failed', leg['navigate_outcome'])
            self.assertEqual(leg['monitors_fired'],
                             ['(S_zone IN ZONE109)', '(S_us-threshold sensors-list)'])
            self.assertEqual(leg['outcome'], 'as the scenario says')
            self.assertEqual(leg['bumper_hits'] + leg['body_contacts'], 0)
            self.assertEqual(r['outcome'], 'succeeded')
            # The bag carries the scenario: bag_report judges the mission as the live run did.
            replayed = os.path.join(d, 'bag.json')
            out = subprocess.run([find_tool('bag_report'), bag, '--json', replayed],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=120)
            self.assertEqual(out.returncode, 0, out.stdout[-2000:])
            self.assertNotIn('no /demo_report/scenario', out.stdout)
            with open(replayed) as f:
                b = json.load(f)
            self.assertEqual(b['outcome'], r['outcome'])
            self.assertEqual([(l['mission'], l['outcome'], l['monitors_fired']) for l in b['legs']],
                             [(l['mission'], l['outcome'], l['monitors_fired']) for l in r['legs']])

    def test_plots_refuse_a_file_that_is_not_a_bag_by_its_name(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, 'not_a.bag')
            with open(path, 'w') as f:
                f.write('world: hilare_room\n')
            out = subprocess.run([sys.executable, PLOTS, path, d], stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True, timeout=60)
            self.assertEqual(out.returncode, 1, out.stdout)
            self.assertIn(path + ':', out.stdout)
            self.assertFalse(os.path.exists(os.path.join(d, 'path.png')))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'scenario_run_test', ScenarioRun, sys.argv)
