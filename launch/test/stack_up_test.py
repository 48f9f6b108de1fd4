#!/usr/bin/env python3
# A stack's launch file starts cleanly (launch/test/stack_up.test, one run per stack): every node
# it names is registered and answers a ping, every topic it names delivers a message, every
# action server it names is up, and the nodes talk to each other: for each edge "topic
# publisher subscriber" the master has that publisher and that subscriber on that topic.
# Python because rosnode and the master's API are Python's.
import time
import unittest

import rosgraph
import rosnode
import rospy
import rostest
import rostopic

PKG = 'spott_launch'


def param_list(name):
    """stacks/common.yaml's list and the stack's own (stack_<name>) together."""
    value = []
    for key in (name, 'stack_' + name):
        v = rospy.get_param('~' + key, [])
        value += v.split() if isinstance(v, str) else v
    return value


class StackUp(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('stack_up_test')
        cls.timeout = rospy.get_param('~timeout_s', 60.0)

    def wait(self, ok):
        """Wall seconds, not sim: the stack's clock may not run yet."""
        deadline = time.time() + self.timeout
        while time.time() < deadline:
            if ok():
                return True
            time.sleep(0.1)
        return False

    def test_every_node_is_up_and_answers(self):
        for node in param_list('nodes'):
            name = node if node.startswith('/') else '/' + node
            self.assertTrue(self.wait(lambda: name in rosnode.get_node_names()),
                            'node %s never registered (up: %s)' %
                            (name, ', '.join(sorted(rosnode.get_node_names()))))
            self.assertTrue(rosnode.rosnode_ping(name, max_count=1, verbose=False),
                            'node %s registered but does not answer a ping' % name)

    def test_every_topic_delivers(self):
        # Every topic is listened to at once: the slowest sets the time, not their sum.
        topics = param_list('topics')
        for topic in topics:
            # The type is looked up from the master once the topic is advertised.
            self.assertTrue(self.wait(lambda: rostopic.get_topic_type(topic)[0]),
                            'nobody advertises %s' % topic)
        received = {topic: [] for topic in topics}
        subs = [rospy.Subscriber(topic, rospy.AnyMsg, lambda m, t=topic: received[t].append(1))
                for topic in topics]
        self.wait(lambda: all(received.values()))
        for sub in subs:
            sub.unregister()
        silent = [topic for topic in topics if not received[topic]]
        self.assertEqual(silent, [], 'advertised but delivered nothing in %.0f s' % self.timeout)

    def test_every_action_server_is_up(self):
        for action in param_list('actions'):
            # An actionlib server advertises <action>/status and publishes it periodically.
            status = action.rstrip('/') + '/status'
            self.assertTrue(self.wait(lambda: rostopic.get_topic_type(status)[0]),
                            'no action server on %s' % action)

    def test_the_nodes_talk_to_each_other(self):
        master = rosgraph.Master('/stack_up_test')
        for edge in param_list('edges'):
            topic, pub, sub = edge.split()
            pub, sub = '/' + pub.lstrip('/'), '/' + sub.lstrip('/')

            def connected():
                pubs, subs, _ = master.getSystemState()
                return (pub in dict(pubs).get(topic, []) and sub in dict(subs).get(topic, []))

            ok = self.wait(connected)
            pubs, subs, _ = master.getSystemState()
            self.assertTrue(ok, '%s: expected %s -> %s; publishers %s, subscribers %s' %
                            (topic, pub, sub, dict(pubs).get(topic, []), dict(subs).get(topic, [])))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'stack_up_test', StackUp)
