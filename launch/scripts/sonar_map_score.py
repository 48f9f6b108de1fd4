#!/usr/bin/python3
"""Scores the TR+ controller's sonar map (spott_tr_plus sensor_mapper.h, MAP_OBJECTS_WITH_SONAR)
in recorded runs (./spott run ... --out DIR writes DIR/run.bag) against the world file.

The map: the LINE_SEGMENT features the controller kept at the end of the run (/map_updates:
added, less removed) whose attribute `sensor` is --sensor (sonar).
Precision (issue 19: "a segment matches a wall within 10 cm and 5 degrees"): of those segments,
the ones on a wall's line: every point along the segment (every 2 cm) lies within --distance
(0.10 m) of a wall's solid (its centre line widened by half the world's wall thickness), of a
door's opening in that wall, a closed or unknown door's leaf or an object's footprint, and the
segment's direction is within --angle (5 degrees) of that surface's. Strict precision: the same
without door openings (a segment reaching into a doorway narrows it), also by length.
Recall: of the walls bounding --rooms (default the hallway, hall_w and hall_e; door openings
left out), the share of their length (sampled every 2 cm) lying within --distance of a segment
on a wall's line, projected inside it (half a cell of slack at its ends: segments join cell
centres).
Usage: launch/scripts/sonar_map_score.py --world spott_worlds/worlds/cim_office.yaml RUN.bag...
"""
import argparse
import math

import rosbag
import yaml
from world_shapes import inside

STEP = 0.02  # sampling along walls and segments (m)
LINE_SEGMENT = 1


def door_gaps(world):
    """Door openings as (centre, half width, leaf): leaf when the door may be closed."""
    gaps = []
    for d in world.get("doors", []):
        leaf = d.get("kind", "door") == "door" and d.get("state", "unknown") != "open"
        gaps.append((tuple(d["center"]), d["width"] / 2, leaf))
    return gaps


def in_gap(p, direction, gaps):
    """The gap p lies in (on the wall's line, within half the door's width), or None."""
    for c, half, leaf in gaps:
        dx, dy = p[0] - c[0], p[1] - c[1]
        along = dx * direction[0] + dy * direction[1]
        across = -dx * direction[1] + dy * direction[0]
        if abs(across) < 0.05 and abs(along) < half:
            return leaf
    return None


def surfaces(world):
    """Samples of every real surface: (x, y, direction angle, half thickness, on_wall_edge)."""
    thickness = world.get("walls", {}).get("thickness", 0.1)
    gaps = door_gaps(world)
    seen = set()
    out = []
    edges = []
    for r in world["rooms"]:
        poly = r["polygon"]
        edges += list(zip(poly, poly[1:] + poly[:1]))
    for w in world.get("walls", {}).get("segments", []) or []:
        edges.append((w["from"], w["to"]))
    for a, b in edges:
        length = math.dist(a, b)
        if length < 1e-9:
            continue
        u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        angle = math.atan2(u[1], u[0]) % math.pi
        for i in range(int(length / STEP) + 1):
            p = (a[0] + u[0] * i * STEP, a[1] + u[1] * i * STEP)
            key = (round(p[0] / STEP), round(p[1] / STEP))
            if key in seen:
                continue
            seen.add(key)
            leaf = in_gap(p, u, gaps)
            if leaf is None:
                out.append((p[0], p[1], angle, thickness / 2, "wall"))
            elif leaf:
                out.append((p[0], p[1], angle, 0.03, "leaf"))
            else:
                out.append((p[0], p[1], angle, thickness / 2, "gap"))
    for o in world.get("objects", []):
        x, y, yaw = o["pose"]
        sx, sy = o["size"]
        if o["kind"] == "cylinder":
            n = max(8, int(math.pi * sx / STEP))
            for i in range(n):
                t = 2 * math.pi * i / n
                out.append((x + sx / 2 * math.cos(t), y + sx / 2 * math.sin(t),
                            (t + math.pi / 2) % math.pi, 0.0, "object"))
            continue
        c, s = math.cos(yaw), math.sin(yaw)
        corners = [(u * sx / 2, v * sy / 2) for u, v in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        corners = [(x + c * u - s * v, y + s * u + c * v) for u, v in corners]
        for a, b in zip(corners, corners[1:] + corners[:1]):
            length = math.dist(a, b)
            angle = math.atan2(b[1] - a[1], b[0] - a[0]) % math.pi
            for i in range(int(length / STEP) + 1):
                f = i * STEP / length
                out.append((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), angle, 0.0,
                            "object"))
    return out


class Grid:
    """Surface samples bucketed on a 0.5 m grid for near lookups."""

    def __init__(self, samples):
        self.cells = {}
        for s in samples:
            self.cells.setdefault((int(s[0] // 0.5), int(s[1] // 0.5)), []).append(s)

    def near(self, p, reach):
        ix, iy = int(p[0] // 0.5), int(p[1] // 0.5)
        k = int(math.ceil(reach / 0.5))
        for dx in range(-k, k + 1):
            for dy in range(-k, k + 1):
                for s in self.cells.get((ix + dx, iy + dy), []):
                    if abs(s[0] - p[0]) <= reach and abs(s[1] - p[1]) <= reach:
                        yield s


def angle_between(a, b):
    d = abs(a - b) % math.pi
    return min(d, math.pi - d)


def matches(segment, grid, distance, angle, kinds=("wall", "leaf", "object")):
    """Whether every point along the segment lies within `distance` of a surface's solid (of
    `kinds`; "gap": an open doorway on its wall's line) whose direction is within `angle` of the
    segment's."""
    (ax, ay), (bx, by) = segment
    length = math.hypot(bx - ax, by - ay)
    direction = math.atan2(by - ay, bx - ax) % math.pi
    n = max(1, int(length / STEP))
    for i in range(n + 1):
        p = (ax + (bx - ax) * i / n, ay + (by - ay) * i / n)
        if not any(s[4] in kinds and math.dist(p, s[:2]) - s[3] <= distance and
                   angle_between(direction, s[2]) <= angle
                   for s in grid.near(p, distance + 0.1)):
            return False
    return True


def on_boundary(p, polygon):
    for a, b in zip(polygon, polygon[1:] + polygon[:1]):
        length = math.dist(a, b)
        u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        dx, dy = p[0] - a[0], p[1] - a[1]
        along = dx * u[0] + dy * u[1]
        if abs(-dx * u[1] + dy * u[0]) < 1e-6 and -1e-6 <= along <= length + 1e-6:
            return True
    return False


def bounding_walls(samples, rooms, ids):
    """Wall samples on the outline of the union of rooms `ids` (not between two of them)."""
    polygons = [r["polygon"] for r in rooms if r["id"] in ids]
    out = []
    for s in samples:
        if s[4] != "wall" or not any(on_boundary(s[:2], poly) for poly in polygons):
            continue
        # Between two of the rooms (an inner edge): both sides inside.
        nx, ny = -math.sin(s[2]) * 0.2, math.cos(s[2]) * 0.2
        sides = [any(inside((s[0] + k * nx, s[1] + k * ny), poly) for poly in polygons)
                 for k in (-1, 1)]
        if not all(sides):
            out.append(s)
    return out


def covered(sample, segments, distance, slack):
    for (ax, ay), (bx, by) in segments:
        length = math.hypot(bx - ax, by - ay)
        if length < 1e-9:
            continue
        u = ((bx - ax) / length, (by - ay) / length)
        dx, dy = sample[0] - ax, sample[1] - ay
        along = dx * u[0] + dy * u[1]
        if -slack <= along <= length + slack and \
                abs(-dx * u[1] + dy * u[0]) - sample[3] <= distance:
            return True
    return False


def read_segments(bag_path, sensor):
    kept = {}
    points = 0
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=["/map_updates"]):
            for f in msg.added:
                attributes = {a.key: a.value for a in f.attributes}
                if attributes.get("sensor") != sensor:
                    continue
                if f.type == LINE_SEGMENT and len(f.points) >= 2:
                    kept[f.id] = ((f.points[0].x, f.points[0].y), (f.points[1].x, f.points[1].y))
                else:
                    kept[f.id] = None
            for fid in msg.removed:
                kept.pop(fid, None)
    segments = [s for s in kept.values() if s is not None]
    points = sum(1 for s in kept.values() if s is None)
    return segments, points


def score(bag_path, world, args, grid, hall):
    segments, points = read_segments(bag_path, args.sensor)
    angle = math.radians(args.angle)
    good = [s for s in segments if matches(s, grid, args.distance, angle)]
    on_line = [s for s in segments
               if matches(s, grid, args.distance, angle, ("wall", "leaf", "object", "gap"))]
    length = sum(math.dist(*s) for s in segments)
    good_length = sum(math.dist(*s) for s in good)
    hit = sum(1 for s in hall if covered(s, on_line, args.distance, args.slack))
    return {
        "segments": len(segments), "matched": len(good), "on_line": len(on_line),
        "points": points, "length_m": length, "matched_length_m": good_length,
        "wall_m": len(hall) * STEP, "covered_m": hit * STEP,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--world", required=True)
    parser.add_argument("--sensor", default="sonar")
    parser.add_argument("--rooms", default="hall_w,hall_e")
    parser.add_argument("--distance", type=float, default=0.10)
    parser.add_argument("--angle", type=float, default=5.0, help="degrees")
    parser.add_argument("--slack", type=float, default=0.05)
    parser.add_argument("bags", nargs="+")
    args = parser.parse_args()
    with open(args.world) as f:
        world = yaml.safe_load(f)
    samples = surfaces(world)
    grid = Grid(samples)
    hall = bounding_walls(samples, world["rooms"], set(args.rooms.split(",")))
    total = {}
    for path in args.bags:
        r = score(path, world, args, grid, hall)
        for k, v in r.items():
            total[k] = total.get(k, 0) + v
        print("%s: %d segments (%.1f m), %d on a wall's line, %d on surfaces only (%.1f m), "
              "%d points; walls of %s %.1f m, %.1f m covered" %
              (path, r["segments"], r["length_m"], r["on_line"], r["matched"],
               r["matched_length_m"], r["points"], args.rooms, r["wall_m"], r["covered_m"]))
    if total.get("segments"):
        print("precision %.3f (%d / %d on a wall's line); strict %.3f (%d on surfaces only, no "
              "part in a doorway), %.3f by length; recall %.3f (%.1f of %.1f m)"
              % (total["on_line"] / total["segments"], total["on_line"], total["segments"],
                 total["matched"] / total["segments"], total["matched"],
                 total["matched_length_m"] / max(total["length_m"], 1e-9),
                 total["covered_m"] / max(total["wall_m"], 1e-9), total["covered_m"],
                 total["wall_m"]))
    else:
        print("no %s segment in the runs; recall 0" % args.sensor)


if __name__ == "__main__":
    main()
