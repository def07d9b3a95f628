"""The ``ros2`` command line of the ROS 2 beginner tutorials, run against a
live turtletui graph.

Students type the real commands (same arguments, parsed with argparse as
ros2cli parses them; message values read with PyYAML's ``safe_load``; same
output) and practise them safely on the simulated graph. A plain library:
no Textual, no terminal I/O (only `ros2 bag` reads and writes bag files); a
front end shows the lines and drives the simulation.

API
---
``cli = Ros2Cli(sim)`` wraps a Simulation (or a Graph).

``cli.run(line) -> CommandResult`` interprets one command line (the leading
``ros2`` is optional) and never raises:

* ``result.lines`` -- what the command prints at once (list of str, no newlines);
* ``result.error`` -- True when the command failed; ``lines`` is then exactly
  one line, e.g. ``ros2: error: invalid choice: 'topik' (did you mean 'topic'?)``;
* ``result.stream`` -- for commands that go on (``topic echo``, ``topic hz``,
  ``topic pub`` without ``--once``, ``service call``, ``action send_goal``,
  ``bag record``, ``bag play``) a
  :class:`Stream`, else None. After each simulation step call
  ``stream.poll()`` for the lines printed since the last poll;
  ``stream.done`` turns True when the command ended by itself (``--once``, a
  response, a result); ``stream.close()`` stops it, as Ctrl+C does (its hidden
  node and everything on it go; a running goal is canceled). Streams buffer
  at most ``MAX_BUFFERED_LINES`` lines between polls (oldest whole messages
  first) and ``topic pub`` publishes at ``MAX_PUB_RATE_HZ`` at most.

``cli.streams`` holds the streams still running, ``cli.close_all()`` stops
them. :class:`Terminal` adds what a shell adds around ``ros2``: one command
in the foreground, Ctrl+C, publishers and recordings in the background
(``jobs``, ``kill``).

Commands: ``node list|info``, ``topic list|echo|hz|info|type|find|pub``,
``service list|type|find|info|call``, ``param list|get|set|dump``,
``action list|info|send_goal``, ``interface show|list|packages|package``,
``bag record|info|play`` (bags in the folder turtletui runs in; ``record``
and ``play`` need a Simulation, not a bare Graph); ``-h`` on each prints its
help. What rcl gives every node is shown as the real tools show it
(``/parameter_events``, ``/rosout``, the parameter services: see
graph.introspection.with_ros_plumbing) though turtletui's graph keeps none of
it: ``topic echo /rosout`` prints the log, and a parameter service call
points at ``ros2 param``. So are an action's hidden topics and services
(``<action>/_action/...``: graph.action_endpoints), shown only with the
``--include-hidden-*`` options as ros2cli does; nothing travels on them, and
``topic echo``/``hz`` and ``service call`` there say so. Not modelled: QoS options, service recording
(``bag record --services``), ``ros2 run``/``launch``.
"""

from turtletui.ros2cli.cli import Ros2Cli
from turtletui.ros2cli.common import CommandResult
from turtletui.ros2cli.streams import MAX_BUFFERED_LINES, Stream
from turtletui.ros2cli.terminal import Terminal
from turtletui.ros2cli.topic import MAX_PUB_RATE_HZ
from turtletui.ros2cli.values import YamlError, parse_yaml, yaml_lines

__all__ = [
    "MAX_BUFFERED_LINES",
    "MAX_PUB_RATE_HZ",
    "CommandResult",
    "Ros2Cli",
    "Stream",
    "Terminal",
    "YamlError",
    "parse_yaml",
    "yaml_lines",
]
