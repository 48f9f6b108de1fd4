#!/usr/bin/env python3
# The ROS command line works on SPOTT-ROS's messages (Debian ships the Python message packages
# separately: without them `rostopic echo` fails with "Cannot load message class"). For every
# message type of spott_msgs a `rostopic echo -n 1` runs while this test publishes one message of
# that type; every service and action type loads; `rosservice call` gets an answer from
# world_server. Python because the tools under test are Python.
import glob
import os
import subprocess
import sys
import time
import unittest

import rospkg
import rospy
import rostest
from roslib.message import get_message_class, get_service_class

PKG = 'spott_launch'


def spott_types(kind):
    d = os.path.join(rospkg.RosPack().get_path('spott_msgs'), kind)
    ext = '.' + kind
    return sorted('spott_msgs/' + os.path.basename(f)[:-len(ext)] for f in glob.glob(d + '/*' + ext))


class CommandLine(unittest.TestCase):
    def test_rostopic_echo_prints_one_message_of_every_type(self):
        types = spott_types('msg')
        self.assertGreater(len(types), 20)
        publishers = {}
        for t in types:
            cls = get_message_class(t)
            self.assertIsNotNone(cls, t)
            pub = rospy.Publisher('/cli_probe/' + t.split('/')[1], cls, queue_size=1, latch=True)
            pub.publish(cls())
            publishers[t] = pub
        # A few echoes at a time: each is a Python process importing rospy and the message
        # module, and dozens at once on two cores starve each other past any timeout.
        failures = []
        for start in range(0, len(types), 6):
            batch = types[start:start + 6]
            echoes = {t: subprocess.Popen(['rostopic', 'echo', '-n', '1',
                                           '/cli_probe/' + t.split('/')[1]],
                                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                          text=True) for t in batch}
            for t, p in echoes.items():
                try:
                    out, _ = p.communicate(timeout=90)
                except subprocess.TimeoutExpired:
                    p.kill()
                    out = p.communicate()[0]
                    failures.append('%s: no message echoed in 90 s: %s' % (t, out[-300:]))
                    continue
                if p.returncode != 0 or '---' not in out:
                    failures.append('%s: exit %s: %s' % (t, p.returncode, out[-300:]))
        self.assertEqual(failures, [])

    def test_every_service_and_action_type_loads(self):
        for t in spott_types('srv'):
            self.assertIsNotNone(get_service_class(t), t)
        for t in spott_types('action'):
            self.assertIsNotNone(get_message_class(t + 'Action'), t)
            self.assertIsNotNone(get_message_class(t + 'Feedback'), t)

    def test_rosservice_call_answers(self):
        rospy.wait_for_service('/world_server/locate_room', timeout=60)
        out = subprocess.run(['rosservice', 'call', '/world_server/locate_room',
                              '{point: {x: 1.2, y: 8.25, z: 0.0}}'],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=60)
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertIn('room_id: "hall_w"', out.stdout)

    def test_stack_launch_refuses_an_unsupported_value_naming_the_accepted_ones(self):
        for arg, accepted in (('localization:=amcl',
                               'localization_must_be_markov_truth_odometry_or_sensed'),
                              ('controller:=bt', 'controller_must_be_tr_plus_or_none'),
                              ('executive:=smach', 'executive_must_be_rpl_or_none')):
            out = subprocess.run(['roslaunch', '--nodes', 'spott_launch', 'stack.launch',
                                  arg], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 text=True, timeout=120)
            self.assertNotEqual(out.returncode, 0, arg)
            self.assertIn(accepted, out.stdout, arg)
        out = subprocess.run(['roslaunch', '--nodes', 'spott_launch', 'stack.launch'],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=120)
        self.assertEqual(out.returncode, 0, out.stdout[-500:])

    def test_replay_and_demo_launch_files_parse_with_a_scenarios_arguments(self):
        # roslaunch loads the rosparam files while parsing: real ones.
        scenario = os.path.join(rospkg.RosPack().get_path(PKG), 'scenarios', 'bonn_kidnap.yaml')
        config = os.path.join(rospkg.RosPack().get_path(PKG), 'config', 'demo_cim_office.yaml')
        for launch, args in (('replay.launch', ['bag:=/tmp/run.bag']),
                             ('demo.launch', ['bag:=/tmp/run.bag', 'faults_file:=' + scenario,
                                              'params_file:=' + config,
                                              'start_pose:=1 2 0.5'])):
            out = subprocess.run(['roslaunch', '--nodes', 'spott_launch', launch] + args,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=120)
            self.assertEqual(out.returncode, 0, launch + ': ' + out.stdout[-800:])
            self.assertIn('/record' if launch == 'demo.launch' else '/play', out.stdout)


if __name__ == '__main__':
    rospy.init_node('command_line_test')
    rostest.rosrun(PKG, 'command_line_test', CommandLine, sys.argv)
