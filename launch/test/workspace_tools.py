# What the Python rostests of spott_launch share: the workspace's programs of the package.
import catkin.find_in_workspaces as fiw

PKG = 'spott_launch'


def find_tool(name):
    """The workspace's lib/spott_launch/<name>, as rosrun finds it."""
    found = fiw.find_in_workspaces(['libexec'], project=PKG, path=name)
    if not found:
        raise RuntimeError(name + ' not built')
    return found[0]
