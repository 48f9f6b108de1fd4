#!/usr/bin/env python3
# Writes launch/rviz/{spott,rhino,hilare}.rviz, one rviz configuration per stack, from the display
# lists below (a display is defined once and shared). Run it after changing a list:
#   launch/scripts/make_rviz_configs.py
# The stacks (launch/launch/*.launch) and their topics: launch/README.md, "Stacks".
import os

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
RVIZ = os.path.join(HERE, '..', 'rviz')


def display(cls, name, enabled=True, **props):
    d = {'Class': cls, 'Name': name, 'Enabled': enabled, 'Value': enabled}
    d.update(props)
    return d


def marker(name, topic, enabled=True):
    return display('rviz/Marker', name, enabled, **{'Marker Topic': topic, 'Namespaces': {},
                                                   'Queue Size': 100})


def markers(name, topic, enabled=True):
    return display('rviz/MarkerArray', name, enabled, **{'Marker Topic': topic,
                                                        'Namespaces': {}, 'Queue Size': 100})


def occupancy(name, topic, scheme, alpha, enabled=True, behind=False):
    return display('rviz/Map', name, enabled, **{'Alpha': alpha, 'Color Scheme': scheme,
                                                'Draw Behind': behind, 'Topic': topic,
                                                'Unreliable': False, 'Use Timestamp': False})


def cones(name, topic, color, enabled=True):
    # One sensor_msgs/Range per transducer, each in its own frame: the buffer keeps the ring.
    return display('rviz/Range', name, enabled, **{'Alpha': 0.4, 'Buffer Length': 24,
                                                  'Color': color, 'Queue Size': 100,
                                                  'Topic': topic})


GRID = display('rviz/Grid', 'Grid (1 m)', **{
    'Alpha': 0.5, 'Cell Size': 1, 'Color': '160; 160; 164',
    'Line Style': {'Line Width': 0.03, 'Value': 'Lines'}, 'Normal Cell Count': 0,
    'Offset': {'X': 0, 'Y': 0, 'Z': 0}, 'Plane': 'XY', 'Plane Cell Count': 40,
    'Reference Frame': '<Fixed Frame>'})
MAP = occupancy('Map (CAD walls)', '/map', 'map', 1, behind=True)
WORLD = markers('World (rooms, doors, walls)', '/world_markers')
ROBOT = display('rviz/RobotModel', 'Robot (URDF)', **{
    'Alpha': 1, 'Robot Description': 'robot_description', 'TF Prefix': '',
    'Update Interval': 0, 'Visual Enabled': True, 'Collision Enabled': False})
GLOBAL = markers('Global path and projected goal', '/global_planner_markers')
WINDOW = display('rviz/Polygon', 'Local window', **{'Alpha': 1, 'Color': '0; 170; 255',
                                                    'Topic': '/local_window',
                                                    'Unreliable': False})
POTENTIAL = occupancy('Harmonic potential', '/harmonic_planner/potential', 'costmap', 0.6,
                      enabled=False)
CONTOURS = marker('Equipotential contours', '/harmonic_planner/contours')
PATH = display('rviz/Path', 'Predicted path', **{
    'Alpha': 1, 'Buffer Length': 1, 'Color': '25; 255; 0', 'Line Style': 'Lines',
    'Line Width': 0.03, 'Offset': {'X': 0, 'Y': 0, 'Z': 0.1}, 'Pose Style': 'None',
    'Topic': '/harmonic_planner/path', 'Unreliable': False})
BELIEF = occupancy('Localization belief (marginal over heading)', '/belief', 'costmap', 0.5)
MODES = display('rviz/PoseArray', 'Localization modes', **{
    'Alpha': 1, 'Arrow Length': 0.5, 'Axes Length': 0.3, 'Axes Radius': 0.01,
    'Color': '255; 170; 0', 'Head Length': 0.07, 'Head Radius': 0.05, 'Queue Size': 10,
    'Shaft Length': 0.23, 'Shaft Radius': 0.02, 'Shape': 'Arrow (Flat)',
    'Topic': '/localization_modes', 'Unreliable': False})
ESTIMATE = display('rviz/PoseWithCovariance', 'Estimate (amcl_pose)', **{
    'Alpha': 1, 'Axes Length': 1, 'Axes Radius': 0.1,
    'Color': '255; 25; 0', 'Head Length': 0.15, 'Head Radius': 0.12, 'Shaft Length': 0.45,
    'Shaft Radius': 0.04, 'Shape': 'Arrow', 'Topic': '/amcl_pose', 'Unreliable': False,
    'Covariance': {'Orientation': {'Alpha': 0.5, 'Color': '255; 255; 127', 'Color Style': 'Unique',
                                   'Frame': 'Local', 'Offset': 1, 'Scale': 1, 'Value': True},
                   'Position': {'Alpha': 0.3, 'Color': '204; 51; 204', 'Scale': 1,
                                'Value': True},
                   'Value': True}})
SONAR = cones('Sonar cones', '/sonar/range', '255; 255; 0')
INFRARED = cones('Infrared cones', '/infrared/range', '255; 85; 255')
LASER = display('rviz/LaserScan', 'Laser', **{
    'Alpha': 1, 'Color': '0; 255; 255', 'Color Transformer': 'FlatColor', 'Decay Time': 0,
    'Position Transformer': 'XYZ', 'Queue Size': 10, 'Selectable': True, 'Size (m)': 0.05,
    'Style': 'Flat Squares', 'Topic': '/scan', 'Unreliable': False, 'Use Fixed Frame': True})
ARBITER = marker("Wheels (arbiter's driver)", '/cmd_vel_arbiter/driver_marker')
BUMPER = markers('Bumper contacts', '/bumper_markers')
TR_RULE = marker('TR+ firing rule', '/tr_plus_controller/firing_rule_marker')
RPL_TEXT = marker('RPL task tree and monitors (text)', '/rpl_executive/text_view')
NC_MARKERS = markers('Noreils-Chatila monitors', '/rpl_executive/markers')
TF = display('rviz/TF', 'TF', enabled=False, **{
    'Frame Timeout': 15, 'Marker Alpha': 1, 'Marker Scale': 1, 'Show Arrows': True,
    'Show Axes': True, 'Show Names': True, 'Update Interval': 0})
# The simulator's own view: what the real robot would not have.
TRUTH = display('rviz/Odometry', 'Ground truth (robot_sim)', **{
    'Angle Tolerance': 0, 'Position Tolerance': 0, 'Keep': 1, 'Queue Size': 10,
    'Shape': {'Alpha': 1, 'Axes Length': 1, 'Axes Radius': 0.1, 'Color': '0; 255; 255',
              'Head Length': 0.15, 'Head Radius': 0.12, 'Shaft Length': 0.45,
              'Shaft Radius': 0.04, 'Value': 'Arrow'},
    'Covariance': {'Value': False}, 'Topic': '/sim/ground_truth', 'Unreliable': False})
OCTOMAP = markers('OctoMap (the world as simulated)', '/sim/octomap_markers', enabled=False)


def group(name, displays):
    return {'Class': 'rviz/Group', 'Name': name, 'Enabled': True, 'Value': True,
            'Displays': displays}


COMMON = [GRID, MAP, WORLD, ROBOT, GLOBAL, WINDOW, POTENTIAL, CONTOURS, PATH, BELIEF, MODES,
          ESTIMATE, SONAR]
SIM = group('Simulation only', [TRUTH, OCTOMAP])
STACKS = {
    # SPOTT on the Nomad 200 and the B-12 (cim_office).
    'spott': (COMMON + [INFRARED, TR_RULE, ARBITER, BUMPER, TF, SIM], (15, 10), 29),
    # RHINO-style delivery on the B21 (bonn_department).
    'rhino': (COMMON + [LASER, RPL_TEXT, ARBITER, BUMPER, TF, SIM], (13.5, 10), 32),
    # Noreils and Chatila's missions on HILARE (hilare_room).
    'hilare': (COMMON + [LASER, RPL_TEXT, NC_MARKERS, ARBITER, BUMPER, TF, SIM], (5.25, 4.5), 70),
}


def config(displays, centre, scale):
    return {
        'Panels': [{'Class': 'rviz/Displays', 'Help Height': 0, 'Name': 'Displays',
                    'Property Tree Widget': {'Expanded': None, 'Splitter Ratio': 0.5},
                    'Tree Height': 500}],
        'Visualization Manager': {
            'Class': '',
            'Displays': displays,
            'Enabled': True,
            'Global Options': {'Background Color': '48; 48; 48', 'Default Light': True,
                               'Fixed Frame': 'map', 'Frame Rate': 30},
            'Name': 'root',
            'Tools': [{'Class': 'rviz/Interact', 'Hide Inactive Objects': True},
                      {'Class': 'rviz/MoveCamera'}, {'Class': 'rviz/Select'},
                      {'Class': 'rviz/SetInitialPose', 'Theta std deviation': 0.2617993950843811,
                       'Topic': '/initialpose', 'X std deviation': 0.5, 'Y std deviation': 0.5},
                      {'Class': 'rviz/SetGoal', 'Topic': '/move_base_simple/goal'},
                      {'Class': 'rviz/Measure'}],
            'Value': True,
            'Views': {'Current': {'Class': 'rviz/TopDownOrtho', 'Invert Z Axis': False,
                                  'Name': 'Current View', 'Near Clip Distance': 0.01,
                                  'Scale': scale, 'Target Frame': '<Fixed Frame>',
                                  'X': centre[0], 'Y': centre[1]},
                      'Saved': None},
        },
        'Window Geometry': {'Displays': {'collapsed': False}, 'Height': 800,
                            'Hide Left Dock': False, 'Hide Right Dock': True, 'Width': 1280,
                            'X': 0, 'Y': 0},
    }


def main():
    for name, (displays, centre, scale) in STACKS.items():
        path = os.path.join(RVIZ, name + '.rviz')
        with open(path, 'w') as f:
            yaml.safe_dump(config(displays, centre, scale), f, sort_keys=False,
                           default_flow_style=False)
        print('wrote', os.path.relpath(path))


if __name__ == '__main__':
    main()
