# What the Python rostests of spott_launch share: the workspace's programs of the package, and a
# scenario run as ./spott run runs it, on the test's master.
import json
import os
import subprocess

import catkin.find_in_workspaces as fiw

PKG = 'spott_launch'


def find_tool(name):
    """The workspace's lib/spott_launch/<name>, as rosrun finds it."""
    found = fiw.find_in_workspaces(['libexec'], project=PKG, path=name)
    if not found:
        raise RuntimeError(name + ' not built')
    return found[0]


def run_scenario(test, scenario, out_dir, extra_args=(), timeout_s=360):
    """scenario_tool turns the scenario file into demo.launch's arguments in out_dir, and
    demo.launch runs the whole stack with them. Returns (the launch arguments, the JSON
    report); `extra_args` are more demo.launch arguments (e.g. a bag)."""
    out = subprocess.run([find_tool('scenario_tool'), scenario, '--out', out_dir],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         timeout=60)
    test.assertEqual(out.returncode, 0, out.stdout)
    with open(os.path.join(out_dir, 'launch_args')) as f:
        args = [a for a in f.read().split('\n') if a]
    report = os.path.join(out_dir, 'report.json')
    run = subprocess.run(
        ['roslaunch', PKG, 'demo.launch'] + args +
        ['params_file:=' + os.path.join(out_dir, 'demo_params.yaml'),
         'faults_file:=' + os.path.join(out_dir, 'faults.yaml'),
         'report_json:=' + report, 'scenario:=' + scenario] + list(extra_args),
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout_s)
    test.assertTrue(os.path.exists(report), run.stdout[-3000:])
    with open(report) as f:
        return args, json.load(f)
