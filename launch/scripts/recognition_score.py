#!/usr/bin/python3
"""Scores the TR+ controller's object recognition (spott_tr_plus object_recognition.h) in
recorded runs (./spott run ... --out DIR writes DIR/run.bag) against the world file.

Precision, per label: of the labelled features the controller kept in the map at the end of the
run (/map_updates: added, less removed), those whose centre lies within --tolerance of the
footprint of a world object of the same kind (a partition 5 m long seen in part is named where
it was seen, not at its middle) (spott_map's kind names: chair, desk, cylinder, cuboid, partition,
shelf). Recall, per kind: of the world objects the robot was near, in the same room, within
--reach of its centre on the ground truth (/sim/ground_truth) for at least one second, those
matched by a feature of their kind. A wrong label is counted under the label given.
Usage: launch/scripts/recognition_score.py --world spott_worlds/worlds/cim_office.yaml RUN.bag...
"""
import argparse
import collections
import math

import rosbag
import yaml
from world_shapes import inside


def room_of(p, rooms):
    for r in rooms:
        if inside(p, r["polygon"]):
            return r["id"]
    return None


def footprint_distance(p, o):
    """From p to the object's footprint (0 inside): a box turned by its yaw, or a circle."""
    x, y, yaw = o["pose"]
    sx, sy = o["size"]
    dx, dy = p[0] - x, p[1] - y
    if o["kind"] == "cylinder":
        return max(0.0, math.hypot(dx, dy) - sx / 2)
    u = math.cos(yaw) * dx + math.sin(yaw) * dy
    w = -math.sin(yaw) * dx + math.cos(yaw) * dy
    return math.hypot(max(0.0, abs(u) - sx / 2), max(0.0, abs(w) - sy / 2))


def score(bag_path, world, reach, tolerance):
    rooms = world["rooms"]
    objects = [dict(o, room=room_of(o["pose"][:2], rooms)) for o in world.get("objects", [])]
    kept = {}
    near_since = {}
    seen = set()
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, t in bag.read_messages(topics=["/map_updates", "/sim/ground_truth"]):
            if topic == "/map_updates":
                for f in msg.added:
                    attributes = {a.key: a.value for a in f.attributes}
                    if f.label and attributes.get("sensor") == "quadris":
                        kept[f.id] = (f.label, f.pose.position.x, f.pose.position.y)
                for fid in msg.removed:
                    kept.pop(fid, None)
                continue
            p = (msg.pose.pose.position.x, msg.pose.pose.position.y)
            here = room_of(p, rooms)
            s = t.to_sec()
            for o in objects:
                close = o["room"] == here and math.dist(p, o["pose"][:2]) <= reach
                if not close:
                    near_since.pop(o["id"], None)
                    continue
                near_since.setdefault(o["id"], s)
                if s - near_since[o["id"]] >= 1.0:
                    seen.add(o["id"])
    results = []  # (label, correct)
    matched = set()
    for label, x, y in kept.values():
        best = None
        for o in objects:
            d = footprint_distance((x, y), o)
            if o["kind"] == label and d <= tolerance and (best is None or d < best[0]):
                best = (d, o["id"])
        results.append((label, best is not None))
        if best:
            matched.add(best[1])
    recall = [(o["kind"], o["id"] in matched) for o in objects if o["id"] in seen]
    return results, recall


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--world", required=True)
    parser.add_argument("--reach", type=float, default=3.0)
    parser.add_argument("--tolerance", type=float, default=0.25)
    parser.add_argument("bags", nargs="+")
    args = parser.parse_args()
    with open(args.world) as f:
        world = yaml.safe_load(f)
    precision = collections.defaultdict(lambda: [0, 0])
    recall = collections.defaultdict(lambda: [0, 0])
    for path in args.bags:
        results, seen = score(path, world, args.reach, args.tolerance)
        for label, ok in results:
            precision[label][0] += ok
            precision[label][1] += 1
        for kind, ok in seen:
            recall[kind][0] += ok
            recall[kind][1] += 1
        print("%s: %d named (%d right); %d objects near, %d of them named" %
              (path, len(results), sum(ok for _, ok in results), len(seen),
               sum(ok for _, ok in seen)))
    print("label: precision (right / named), recall (named / near)")
    for label in sorted(set(precision) | set(recall)):
        p, r = precision[label], recall[label]
        print("  %-10s %s  %s" % (label, "%d / %d" % tuple(p) if p[1] else "-",
                                  "%d / %d" % tuple(r) if r[1] else "-"))


if __name__ == "__main__":
    main()
