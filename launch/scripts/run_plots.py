#!/usr/bin/env python3
# Plots of a recorded run (issue 20), drawn from its bag alone: where people would rather look
# than read the report. Writes into OUT_DIR:
#   path.png       the world's map with the ground-truth path, the localization's estimate,
#                  each leg's end (reached or not is the report's business: the label is the task),
#                  body contacts and lost alarms;
#   certainty.png  the localization's certainty and its position error against the ground truth;
#   speed.png      the robot's real speed (ground truth) and the commanded speed (/cmd_vel);
#   plots.json     the figures the plots show (path length, errors, speeds; per leg how smoothly
#                  the wheels were commanded), so a test or a reader can check them against
#                  report.json.
# Times are simulated seconds from the first ground-truth sample. Messages without a stamp
# (/cmd_vel) are placed on simulated time through /clock as the recorder saw it.
# Usage: run_plots.py BAG OUT_DIR
import json
import math
import os
import sys

import numpy as np

TRUTH, STATUS, CMD, CLOCK = '/sim/ground_truth', '/localization_status', '/cmd_vel', '/clock'
CONTACT, MAP, FAULTS = '/sim/contact', '/map', '/sim/faults'
TASK_GOAL, TASK_RESULT = '/task/goal', '/task/result'
NAV_GOAL, NAV_RESULT = '/harmonic_planner/navigate/goal', '/harmonic_planner/navigate/result'
MISSION_GOAL, MISSION_RESULT = '/mission/goal', '/mission/result'
SPEED_WINDOW_S = 0.2  # the real speed from positions this far apart: the truth's twist is noiseless
                      # but in the body frame of a model that may slide
TURN_REVERSAL_RPS = 0.2  # a turn-rate reversal counts from beyond +-this to beyond -+this
STOP_FROM_MPS = 0.15     # a sudden stop: from above this to 0 in one command
CMD_GAP_S = 0.5  # /cmd_vel comes at 20 Hz while anything drives; a longer silence is drawn as one


class Run:
    """The series of one bag, on simulated time (s)."""

    def __init__(self):
        self.truth = []      # (t, x, y)
        self.status = []     # (t, x, y, certainty, lost)
        self.cmd = []        # (bag time, linear, angular): placed on sim time by `clock`
        self.clock = []      # (bag time, sim time)
        self.contacts = []   # sim times with any segment of the body touching
        self.map = None      # the first nav_msgs/OccupancyGrid
        self.legs = []       # [sim start, label, sim end or None, Navigate target (x, y) or None]
        self.faults = []     # (sim time, text)


def read_bag(path):
    import rosbag
    run = Run()
    legs_by_id = {}
    with rosbag.Bag(path) as bag:
        topics = [TRUTH, STATUS, CMD, CLOCK, CONTACT, MAP, FAULTS, TASK_GOAL, TASK_RESULT,
                  NAV_GOAL, NAV_RESULT, MISSION_GOAL, MISSION_RESULT]
        # The legs are the run's own goals: missions (rpl_executive, which sends Navigate goals
        # of its own), tasks (the TR+ controller, likewise), else Navigate goals.
        by_mission = bag.get_message_count(topic_filters=[MISSION_GOAL]) > 0
        by_task = not by_mission and bag.get_message_count(topic_filters=[TASK_GOAL]) > 0
        goal_topic = MISSION_GOAL if by_mission else TASK_GOAL if by_task else NAV_GOAL
        result_topic = MISSION_RESULT if by_mission else TASK_RESULT if by_task else NAV_RESULT
        for topic, m, t in bag.read_messages(topics=topics):
            if topic == TRUTH:
                p = m.pose.pose.position
                run.truth.append((m.header.stamp.to_sec(), p.x, p.y))
            elif topic == STATUS:
                run.status.append((m.header.stamp.to_sec(), m.estimate.x, m.estimate.y,
                                   m.certainty, bool(m.lost)))
            elif topic == CMD:
                run.cmd.append((t.to_sec(), m.linear.x, m.angular.z))
            elif topic == CLOCK:
                run.clock.append((t.to_sec(), m.clock.to_sec()))
            elif topic == CONTACT:
                if any(m.pressed):
                    run.contacts.append(m.header.stamp.to_sec())
            elif topic == MAP and run.map is None:
                run.map = m
            elif topic == FAULTS:
                for s in m.status:
                    run.faults.append((m.header.stamp.to_sec(), '%s: %s' % (s.hardware_id,
                                                                           s.message)))
            elif topic == goal_topic:
                target = None if by_task or by_mission else (m.goal.target.pose.position.x,
                                                             m.goal.target.pose.position.y)
                label = ('mission ' + m.goal.name if by_mission else m.goal.command if by_task
                         else 'goal (%.1f, %.1f)' % target)
                legs_by_id[m.goal_id.id] = len(run.legs)
                run.legs.append([m.header.stamp.to_sec(), label, None, target])
            elif topic == result_topic:
                i = legs_by_id.pop(m.status.goal_id.id, None)
                if i is None:
                    continue
                if (by_mission and m.result.outcome == 'rejected'
                        and 'not ready' in m.result.message):
                    run.legs[i] = None  # sent again once the executive was ready
                else:
                    run.legs[i][2] = m.header.stamp.to_sec()
    run.legs = [leg for leg in run.legs if leg is not None]
    return run


def on_sim_time(bag_times, clock):
    """Bag (wall) times placed on simulated time by the /clock messages the recorder got."""
    if not clock:
        return np.array(bag_times)
    c = np.array(clock)
    return np.interp(bag_times, c[:, 0], c[:, 1])


def series(run):
    """The arrays and the figures the plots draw; everything a test checks."""
    if len(run.truth) < 2:
        raise ValueError('the bag holds fewer than two ground-truth poses (%s): not a run of '
                         'the simulator' % TRUTH)
    truth = np.array(sorted(run.truth))
    t0 = truth[0, 0]
    out = {'t0': t0, 'truth': truth}
    steps = np.hypot(np.diff(truth[:, 1]), np.diff(truth[:, 2]))
    figures = {'duration_s': float(truth[-1, 0] - t0), 'path_length_m': float(steps.sum())}
    # Real speed: displacement over SPEED_WINDOW_S, centred.
    idx = np.searchsorted(truth[:, 0], truth[:, 0] + SPEED_WINDOW_S)
    idx = np.minimum(idx, len(truth) - 1)
    dt = truth[idx, 0] - truth[:, 0]
    ok = dt > 0.5 * SPEED_WINDOW_S
    speed_t = truth[ok, 0] + 0.5 * dt[ok]
    speed = np.hypot(truth[idx, 1] - truth[:, 1], truth[idx, 2] - truth[:, 2])[ok] / dt[ok]
    out['speed'] = np.column_stack([speed_t, speed]) if ok.any() else np.zeros((0, 2))
    figures['max_speed_mps'] = float(speed.max()) if ok.any() else 0.0
    if run.status:
        s = np.array([(t, x, y, c, float(lost)) for t, x, y, c, lost in sorted(run.status)])
        # The truth at each status' stamp, interpolated as the report does (leg_metrics.cpp).
        inside = (s[:, 0] >= truth[0, 0]) & (s[:, 0] <= truth[-1, 0])
        s = s[inside]
        tx = np.interp(s[:, 0], truth[:, 0], truth[:, 1])
        ty = np.interp(s[:, 0], truth[:, 0], truth[:, 2])
        error = np.hypot(s[:, 1] - tx, s[:, 2] - ty)
        out['status'] = s
        out['error'] = error
        figures['estimates'] = int(len(s))
        figures['max_position_error_m'] = float(error.max()) if len(error) else None
        figures['mean_position_error_m'] = float(error.mean()) if len(error) else None
        lost = s[:, 4] > 0.5
        figures['lost_alarms'] = int(np.count_nonzero(lost[1:] & ~lost[:-1]) + (lost[0] if len(lost) else 0))
    if run.cmd:
        c = np.array(run.cmd)
        out['cmd'] = np.column_stack([on_sim_time(c[:, 0], run.clock), c[:, 1], c[:, 2]])
        figures['max_commanded_speed_mps'] = float(np.abs(c[:, 1]).max())
    figures['contact_samples'] = len(run.contacts)
    figures['legs'] = []
    for start, label, end, target in run.legs:
        leg = {'label': label, 'start_s': start - t0, 'end_s': None if end is None else end - t0,
               'target': target}
        if 'cmd' in out and end is not None:
            c = out['cmd'][(out['cmd'][:, 0] >= start) & (out['cmd'][:, 0] <= end)]
            leg.update(smoothness(c))
        figures['legs'].append(leg)
    out['figures'] = figures
    return out


def smoothness(cmd):
    """How smoothly the wheels were commanded (rows: t, linear, angular): the turn rate's
    reversals beyond +-TURN_REVERSAL_RPS (weaving), its rms, and the stops from above
    STOP_FROM_MPS to 0 from one command to the next (a stutter, or a stop that was meant)."""
    if len(cmd) == 0:
        return {'turn_reversals': 0, 'turn_rms_rps': 0.0, 'sudden_stops': 0}
    sign = np.where(cmd[:, 2] > TURN_REVERSAL_RPS, 1, np.where(cmd[:, 2] < -TURN_REVERSAL_RPS,
                                                              -1, 0))
    sign = sign[sign != 0]
    stops = (cmd[:-1, 1] > STOP_FROM_MPS) & (cmd[1:, 1] == 0.0)
    return {'turn_reversals': int(np.count_nonzero(sign[1:] != sign[:-1])),
            'turn_rms_rps': float(np.sqrt(np.mean(cmd[:, 2] ** 2))),
            'sudden_stops': int(np.count_nonzero(stops))}


def draw(run, data, out_dir):
    import matplotlib
    matplotlib.use('Agg')  # headless: the runs have no display
    import matplotlib.pyplot as plt

    t0, truth = data['t0'], data['truth']
    written = []

    # The path over the map, the figure shaped like the ground it covers.
    pad = 1.5
    xlim = (truth[:, 1].min() - pad, truth[:, 1].max() + pad)
    ylim = (truth[:, 2].min() - pad, truth[:, 2].max() + pad)
    aspect = (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    width = 10.0 if aspect < 1.0 else max(10.0 / aspect, 5.0)
    fig, ax = plt.subplots(figsize=(width, min(max(width * aspect + 1.0, 4.0), 10.0)))
    if run.map is not None:
        info = run.map.info
        grid = np.array(run.map.data, dtype=np.int16).reshape(info.height, info.width)
        shade = np.where(grid < 0, 0.85, 1.0 - np.clip(grid, 0, 100) / 100.0)
        x0, y0 = info.origin.position.x, info.origin.position.y
        ax.imshow(shade, cmap='gray', vmin=0, vmax=1, origin='lower', interpolation='nearest',
                  extent=(x0, x0 + info.width * info.resolution,
                          y0, y0 + info.height * info.resolution))
    ax.plot(truth[:, 1], truth[:, 2], '-', color='tab:blue', lw=1.6, label='ground truth')
    if 'status' in data:
        s = data['status']
        ax.plot(s[:, 1], s[:, 2], '--', color='tab:orange', lw=1.0, label='estimate')
        lost = s[:, 4] > 0.5
        if lost.any():
            ax.plot(np.interp(s[lost, 0], truth[:, 0], truth[:, 1]),
                    np.interp(s[lost, 0], truth[:, 0], truth[:, 2]), '.', color='magenta',
                    ms=4, label='lost (at the true position)')
    ax.plot(truth[0, 1], truth[0, 2], 'o', color='tab:green', ms=8, label='start')
    for i, (start, label, end, _) in enumerate(run.legs):
        if end is None:
            continue
        x, y = np.interp(end, truth[:, 0], truth[:, 1]), np.interp(end, truth[:, 0], truth[:, 2])
        ax.plot(x, y, 's', color='black', ms=6)
        ax.annotate('%d: %s' % (i + 1, label), (x, y), xytext=(5, 5),
                    textcoords='offset points', fontsize=8)
    if run.contacts:
        c = np.array(run.contacts)
        ax.plot(np.interp(c, truth[:, 0], truth[:, 1]), np.interp(c, truth[:, 0], truth[:, 2]),
                'x', color='red', ms=7, label='body contact')
    ax.set_xlabel('x (m, map)')
    ax.set_ylabel('y (m, map)')
    ax.set_aspect('equal')
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.legend(loc='best', fontsize=8)
    ax.set_title('path: %.1f m in %.0f s (simulated)' % (data['figures']['path_length_m'],
                                                         data['figures']['duration_s']))
    written.append(save(fig, out_dir, 'path.png'))

    def mark_legs_and_faults(axes):
        for a in axes:
            for start, _, _, _ in run.legs:
                a.axvline(start - t0, color='gray', lw=0.8, ls=':')
            for t, _ in run.faults:
                a.axvline(t - t0, color='red', lw=0.8, ls='--')

    # Certainty and error.
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(10, 6))
    if 'status' in data:
        s = data['status']
        a1.plot(s[:, 0] - t0, s[:, 3], color='tab:purple', lw=1.0)
        lost = s[:, 4] > 0.5
        a1.fill_between(s[:, 0] - t0, 0, 1, where=lost, color='magenta', alpha=0.2,
                        step='post', label='lost')
        a2.plot(s[:, 0] - t0, data['error'], color='tab:orange', lw=1.0)
        if lost.any():
            a1.legend(loc='lower left', fontsize=8)
    a1.set_ylabel('certainty')
    a1.set_ylim(0, 1.05)
    a2.set_ylabel('position error (m)\nestimate - ground truth')
    a2.set_xlabel('simulated time (s); dotted: a leg starts, dashed: a fault')
    mark_legs_and_faults((a1, a2))
    written.append(save(fig, out_dir, 'certainty.png'))

    # Speeds.
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(10, 6))
    if len(data['speed']):
        a1.plot(data['speed'][:, 0] - t0, data['speed'][:, 1], color='tab:blue', lw=1.4,
                label='real (ground truth)', zorder=2)
    if 'cmd' in data:
        c = with_gaps(data['cmd'], CMD_GAP_S)
        a1.step(c[:, 0] - t0, c[:, 1], where='post', color='tab:gray', lw=0.8,
                label='commanded (/cmd_vel)', zorder=1)
        a2.step(c[:, 0] - t0, c[:, 2], where='post', color='tab:gray', lw=0.8)
    a1.set_ylabel('speed (m/s)')
    a1.legend(loc='upper right', fontsize=8)
    a2.set_ylabel('commanded turn rate (rad/s)')
    a2.set_xlabel('simulated time (s); dotted: a leg starts, dashed: a fault')
    mark_legs_and_faults((a1, a2))
    written.append(save(fig, out_dir, 'speed.png'))
    plt.close('all')
    return written


def with_gaps(samples, gap_s):
    """A NaN row wherever no sample came for gap_s: a silent topic is drawn as a gap, not as a
    ramp between the samples around it."""
    if len(samples) < 2:
        return samples
    cut = np.nonzero(np.diff(samples[:, 0]) > gap_s)[0]
    gaps = np.full((len(cut), samples.shape[1]), np.nan)
    gaps[:, 0] = samples[cut, 0] + 0.5 * gap_s
    return np.insert(samples, cut + 1, gaps, axis=0)


def save(fig, out_dir, name):
    path = os.path.join(out_dir, name)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def main(argv):
    if len(argv) != 3:
        sys.stderr.write('usage: run_plots.py BAG OUT_DIR\n')
        return 2
    bag, out_dir = argv[1], argv[2]
    try:
        run = read_bag(bag)
        data = series(run)
    except Exception as e:  # a bad or foreign bag: say which and why
        sys.stderr.write('%s: %s\n' % (bag, e))
        return 1
    os.makedirs(out_dir, exist_ok=True)
    written = draw(run, data, out_dir)
    with open(os.path.join(out_dir, 'plots.json'), 'w') as f:
        json.dump(data['figures'], f, indent=1)
    print('plots: ' + ', '.join(written))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
