#!/usr/bin/env python3
# The fault campaign's own logic (launch/scripts/fault_campaign.py, issue 21): every drawn fault
# makes a scenario that scenario_tool (the runner's real parser) accepts, with the fault inside
# its kind's window and the same draw for the same seed; a run is judged from its report and log
# as the campaign's table says (no report, a fault after the tasks, a kidnap detected within 30 s
# or not, contacts and lost alarms counted only after the fault, node deaths). Python because the
# campaign is.
import importlib.util
import os
import random
import subprocess
import sys
import tempfile
import unittest

import catkin.find_in_workspaces as fiw
import rospkg
import rostest

PKG = 'spott_launch'


def load_campaign():
    path = os.path.join(rospkg.RosPack().get_path(PKG), 'scripts', 'fault_campaign.py')
    spec = importlib.util.spec_from_file_location('fault_campaign', path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


fc = load_campaign()


def report(outcome='succeeded', fault_time=40.0, lost=(), contacts=(), applied=True):
    return {'outcome': outcome,
            'faults': [{'sim_time_s': fault_time, 'applied': applied}],
            'legs': [{'lost_onsets_s': list(lost[:1]), 'contact_onsets_s': list(contacts[:1])},
                     {'lost_onsets_s': list(lost[1:]), 'contact_onsets_s': list(contacts[1:])}]}


class FaultCampaign(unittest.TestCase):
    def test_every_kind_makes_a_scenario_the_runner_accepts(self):
        tool = fiw.find_in_workspaces(['libexec'], project=PKG, path='scenario_tool')
        self.assertTrue(tool, 'scenario_tool not built')
        with tempfile.TemporaryDirectory() as d:
            for kind in fc.KINDS:
                path = os.path.join(d, kind + '.yaml')
                with open(path, 'w') as f:
                    f.write(fc.scenario_text(kind, 3, fc.draw(kind, random.Random(3))))
                os.makedirs(os.path.join(d, kind))
                out = subprocess.run([tool[0], path, '--out', os.path.join(d, kind)],
                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                     timeout=60)
                self.assertEqual(out.returncode, 0, '%s: %s' % (kind, out.stdout))

    def test_the_same_seed_draws_the_same_fault_within_its_window(self):
        windows = {'kidnap': (20, 60), 'door': (106, 114), 'sonar_dropout': (20, 60),
                   'sonar_stuck': (20, 60), 'quadris_noise': (20, 60), 'slip': (20, 60),
                   'obstacle': (8, 14)}
        self.assertEqual(sorted(windows), sorted(fc.KINDS))
        for kind, (lo, hi) in windows.items():
            for seed in range(1, 21):
                fault = fc.draw(kind, random.Random(seed))
                self.assertEqual(fault, fc.draw(kind, random.Random(seed)), kind)
                self.assertTrue(lo <= fault['time'] <= hi, '%s at %s' % (kind, fault['time']))
        for seed in range(1, 21):  # a kidnap turns 40 to 80 degrees either way
            turn = abs(fc.draw('kidnap', random.Random(seed))['pose'][2])
            self.assertTrue(0.7 <= turn <= 1.4, turn)
        with self.assertRaises(ValueError):
            fc.draw('earthquake', random.Random(1))

    def test_no_report_counts_the_node_deaths(self):
        log = '[robot_sim-3] process has died [pid 1]\n...\n[markov-5] process has died [pid 2]\n'
        row = fc.judge('slip', {'time': 30.0}, None, log)
        self.assertEqual(row['outcome'], 'no report')
        self.assertEqual(row['deaths'], 2)
        self.assertFalse(row['applied'])

    def test_a_fault_after_the_tasks_tested_nothing(self):
        r = report()
        r['faults'] = []
        row = fc.judge('door', {'time': 140.0}, r, '')
        self.assertEqual(row['outcome'], 'fault came after the tasks')

    def test_a_kidnap_is_detected_by_the_first_lost_onset_within_30_s_after_it(self):
        row = fc.judge('kidnap', {'time': 40.0}, report(lost=(12.0, 44.5, 60.0)), '')
        self.assertEqual(row['detected'], 'yes, 4.5 s')  # the onset before the fault is not it
        self.assertTrue(row['applied'])
        late = fc.judge('kidnap', {'time': 40.0}, report(lost=(12.0, 70.5)), '')
        self.assertEqual(late['detected'], 'no')
        none = fc.judge('kidnap', {'time': 40.0}, report(lost=()), '')
        self.assertEqual(none['detected'], 'no')

    def test_the_times_are_the_simulators_not_the_drawn_ones(self):
        # A door waits until nobody stands in it: applied at 151 s, drawn for 140 s.
        row = fc.judge('door', {'time': 140.0}, report(fault_time=151.0, lost=(145.0, 160.0)), '')
        self.assertEqual(row['detected'], 'lost at +9.0 s')

    def test_only_contacts_after_the_fault_are_its_collisions(self):
        row = fc.judge('obstacle', {'time': 10.0},
                       report(fault_time=10.0, contacts=(5.0, 12.0, 30.0)), '')
        self.assertEqual(row['collisions'], 2)
        self.assertEqual(row['detected'], '-')

    def test_a_fault_the_simulator_did_not_apply_is_said(self):
        row = fc.judge('sonar_stuck', {'time': 30.0}, report(applied=False), '')
        self.assertFalse(row['applied'])
        self.assertEqual(row['outcome'], 'succeeded')


if __name__ == '__main__':
    rostest.rosrun(PKG, 'fault_campaign_test', FaultCampaign, sys.argv)
