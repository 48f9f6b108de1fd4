#!/usr/bin/python3
"""Summarizes a Fig. 18 run's bag (fig18_campaign.sh with FIG18_BAG=1) on the ground truth:
the localization's error over the run (mean, max, time over 0.5 m), each bumper contact with
where the robot really was and how far off the estimate was then, the map updates sent (features
added, door states as DoorState's numbers), whether world_server's copy held the controller's
features (those the controller held from 0.3 s before a /map_features message to 0.3 s after it
that the message lacked) and the controller's last firing rule.
Usage: launch/scripts/fig18_bag_summary.py RUN.bag [RUN.bag ...]"""
import bisect
import math
import sys

import rosbag


def yaw_of(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def summarize(path):
    truth_t, truth = [], []
    errors, contacts, updates, rules = [], [], [], []
    life, copies = {}, []  # feature id -> [added, removed] at the owner; world_server's copies
    pressed_before = False
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages():
            s = t.to_sec()
            if topic == "/sim/ground_truth":
                p = msg.pose.pose
                truth_t.append(s)
                truth.append((p.position.x, p.position.y, yaw_of(p.orientation)))
            elif topic == "/localization_status" and truth:
                i = min(bisect.bisect_left(truth_t, s), len(truth) - 1)
                x, y, _ = truth[i]
                errors.append((s, math.hypot(msg.estimate.x - x, msg.estimate.y - y), msg.lost))
            elif topic == "/bumper":
                pressed = any(msg.pressed)
                if pressed and not pressed_before and truth:
                    x, y, th = truth[-1]
                    e = errors[-1][1] if errors else float("nan")
                    segs = [i for i, b in enumerate(msg.pressed) if b]
                    contacts.append((s, x, y, math.degrees(th), e, segs))
                pressed_before = pressed
            elif topic == "/map_updates":
                doors = ["%s:%d" % (d.door_id, d.state)
                         for d in getattr(msg, "doors", [])]
                added = len(getattr(msg, "added", []))
                removed = len(getattr(msg, "removed", []))
                updates.append((s, added, removed, doors))
                for fid in getattr(msg, "removed", []):
                    if fid in life:
                        life[fid][1] = s
                for f in getattr(msg, "added", []):
                    life[f.id] = [s, float("inf")]
            elif topic == "/map_features":
                copies.append((s, {f.id for f in msg.features}))
            elif topic == "/tr_plus_controller/state":
                rules.append((s, msg.firing_program, msg.firing_rule, msg.firing_action))
    print("== %s" % path)
    if errors:
        e = [x[1] for x in errors]
        over = sum(1 for x in e if x > 0.5)
        worst = max(errors, key=lambda x: x[1])
        print("localization: %d estimates, mean error %.2f m, max %.2f m at t=%.1f s, %d over "
              "0.5 m, said lost %d times" % (len(e), sum(e) / len(e), worst[1], worst[0], over,
                                            sum(1 for x in errors if x[2])))
    for s, x, y, th, e, segs in contacts:
        print("contact t=%.1f s at (%.2f, %.2f, %.0f deg), estimate %.2f m off, segments %s"
              % (s, x, y, th, e, segs))
    for s, added, removed, doors in updates:
        print("map update t=%.1f s: %d added, %d removed, doors %s" % (s, added, removed,
                                                                       " ".join(doors) or "-"))
    lacked = sorted({fid for s, ids in copies for fid, (a, r) in life.items()
                     if a <= s - 0.3 and r > s + 0.3 and fid not in ids})
    if copies:
        print("world_server's copy: %d of the controller's %d features lacked at some time%s"
              % (len(lacked), len(life), (" (" + ", ".join(lacked[:6]) + ")") if lacked else ""))
    if rules:
        s, prog, rule, action = rules[-1]
        print("last rule t=%.1f s: %s[%d] %s" % (s, prog, rule, action))


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    for path in sys.argv[1:]:
        summarize(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
