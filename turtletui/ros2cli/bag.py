"""``ros2 bag``: record, info, play, as the official "Recording and playing
back data" tutorial uses them (turtletui.recording.bag does the work)::

    ros2 bag record /turtle1/cmd_vel /turtle1/pose -o subset
    ros2 bag info subset
    ros2 bag play subset

``record`` goes on until Ctrl+C, then the bag folder is written; ``play``
publishes into the live simulation until the bag's end (or Ctrl+C). Both
print what rosbag2's recorder and player log, as in a terminal, and a
console keeps them running in the background, as ``topic pub``. Paths are
relative to the folder turtletui was started in.
"""

from __future__ import annotations

import argparse
import os
from argparse import ArgumentParser, Namespace
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from turtletui.graph.logs import ERROR, LogRecord
from turtletui.recording.bag import (
    PLAYER,
    RECORDER,
    BagError,
    BagPlayback,
    BagRecording,
    bag_info,
    bag_topics,
    rosbag2_node,
)
from turtletui.ros2cli.arguments import Command, Verb
from turtletui.ros2cli.common import (
    CommandError,
    CommandResult,
    PlainError,
    absolute,
    hint,
    live_topic_names,
)
from turtletui.ros2cli.streams import OWNER, Stream

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

STORAGES = ("mcap", "sqlite3")
"""rosbag2's storage plugins; turtletui writes and reads mcap (Jazzy's default)."""


def _ros2bag_error(text: str) -> PlainError:
    """An error as ros2bag prints it (its print_error)."""
    return PlainError(f"[ERROR] [ros2bag]: {text}")


class BagStream(Stream):
    """A rosbag2 command that goes on: its node's log lines are its output."""

    runs_in_background = True

    def __init__(self, cli: Ros2Cli, command: str, node_name: str, start: Callable[[Any], Any]) -> None:
        super().__init__(cli, command, node=rosbag2_node(cli.graph, node_name, f"{OWNER}:{node_name}"))
        self._graph.log_sinks.append(self._on_log)
        try:
            self.work = start(self.node)
            """The BagRecording or BagPlayback."""
        except BaseException:
            self.work = None
            self.close()
            raise

    def _on_log(self, record: LogRecord) -> None:
        if record.node == self.node.name:
            self._emit([record.format()])

    def _on_close(self) -> None:
        try:
            if self.work is not None:
                self.work.stop()
        except BagError as err:
            self._graph.log(self.node.name, ERROR, str(err))
        finally:
            self._graph.log_sinks.remove(self._on_log)


class RecordStream(BagStream):
    """``ros2 bag record``: until Ctrl+C, which writes the bag."""

    @property
    def progress(self) -> str:
        return f"to {self.work.folder}/"


class PlayStream(BagStream):
    """``ros2 bag play``: until the bag's end (never with ``--loop``) or Ctrl+C."""

    @property
    def progress(self) -> str:
        return f"{self.work.published} published"

    def poll(self) -> list[str]:
        if self.work is not None and self.work.done and not self.done:
            self._finish()  # the bag was played to its end
        return super().poll()


def _cli_sim(cli: Ros2Cli) -> Any:
    if cli.sim is None:
        raise CommandError("needs a simulation (this console only has a graph)")
    return cli.sim


# -- record ----------------------------------------------------------------------------

def _record_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("-o", "--output",
                        help="Destination of the bagfile to create, defaults to a timestamped folder "
                             "in the current directory.")
    parser.add_argument("-s", "--storage", default="mcap", choices=STORAGES,
                        help="Storage identifier to be used, defaults to 'mcap'.")
    topics = parser.add_mutually_exclusive_group()
    topics.add_argument("topics_positional", type=str, default=[], metavar="[Topic ...]", nargs="*",
                        help="Space-delimited list of topics to record. (deprecated)")
    topics.add_argument("--topics", type=str, default=[], metavar="Topic", nargs="+",
                        help="Space-delimited list of topics to record.")
    parser.add_argument("-a", "--all", action="store_true",
                        help="Record all topics and services (Exclude hidden topic).")
    parser.add_argument("--all-topics", action="store_true", help="Record all topics (Exclude hidden topic).")


def _record(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    sim = _cli_sim(cli)
    topics = [absolute(name) for name in args.topics_positional or args.topics]
    everything = args.all or args.all_topics
    if not (everything or topics):
        raise _ros2bag_error("Need to specify at least one option out of --all, --all-topics or --topics"
                             " (or topics: ros2 bag record /turtle1/cmd_vel /turtle1/pose)")
    if args.storage != "mcap":
        raise _ros2bag_error(f"turtletui records with the mcap storage only, not {args.storage} (-s mcap)")
    notes = []
    if everything and topics:
        notes.append("[WARN] [ros2bag]: --all or --all-topics will override --topics")
    elif topics:
        live = live_topic_names(cli.graph)
        for name in topics:
            if name not in live:
                notes.append(f"[WARN] [ros2bag]: '{name}' is not published yet: it is recorded once it is"
                             f"{hint(name, live)}")
    def start(node: Any) -> BagRecording:
        return BagRecording(sim, None if everything else topics, args.output, node=node)

    try:
        result = cli.start(RecordStream(cli, line, RECORDER, start))
    except BagError as err:
        raise _ros2bag_error(str(err)) from None
    result.lines[:0] = notes
    return result


# -- info ------------------------------------------------------------------------------

def _bag_path(text: str) -> str:
    """ros2bag's check_path_exists."""
    if not os.path.exists(text):
        raise argparse.ArgumentTypeError(f"Bag path '{text}' does not exist!")
    return text


def _reader_arguments(parser: ArgumentParser) -> None:
    """ros2bag's add_standard_reader_args."""
    parser.add_argument("bag_path", type=_bag_path, help="Bag to open")
    parser.add_argument("-s", "--storage", default="", choices=STORAGES,
                        help="Storage implementation of bag. By default attempts to detect automatically"
                             " - use this argument to override.")


def _info_arguments(parser: ArgumentParser) -> None:
    _reader_arguments(parser)
    parser.add_argument("-t", "--topic-name", action="store_true", help="Only display topic names.")


def _info(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    _check_storage(args.storage)
    try:
        if args.topic_name:
            return CommandResult(bag_topics(args.bag_path))
        return CommandResult(bag_info(args.bag_path).rstrip("\n").split("\n"))
    except BagError as err:
        raise CommandError(str(err)) from None


def _check_storage(storage: str) -> None:
    if storage not in ("", "mcap"):
        raise CommandError(f"turtletui reads bags of the mcap storage only, not {storage}"
                           " (ros2 bag convert turns a sqlite3 bag into mcap)")


# -- play ------------------------------------------------------------------------------

def _positive_rate(text: str) -> float:
    """ros2bag's check_positive_float."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text} is not the valid type (float)") from None
    if not value > 0:
        raise argparse.ArgumentTypeError(f"{text} is not in the valid range (> 0.0)")
    return value


def _play_arguments(parser: ArgumentParser) -> None:
    _reader_arguments(parser)
    parser.add_argument("-r", "--rate", type=_positive_rate, default=1.0,
                        help="rate at which to play back messages. Valid range > 0.0.")
    parser.add_argument("--topics", type=str, default=[], metavar="topic", nargs="+",
                        help="Space-delimited list of topics to play.")
    parser.add_argument("-l", "--loop", action="store_true",
                        help="enables loop playback when playing a bagfile: it starts back at the beginning "
                             "on reaching the end and plays indefinitely.")


def _play(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    sim = _cli_sim(cli)
    _check_storage(args.storage)
    topics = [absolute(name) for name in args.topics] or None

    def start(node: Any) -> BagPlayback:
        return BagPlayback(sim, args.bag_path, rate=args.rate, loop=args.loop, topics=topics, node=node)

    try:
        return cli.start(PlayStream(cli, line, PLAYER, start))
    except BagError as err:
        raise CommandError(str(err)) from None


COMMAND = Command("bag", "Various rosbag related sub-commands", verbs=(
    Verb("info", "Print information about a bag to the screen", _info_arguments, _info),
    Verb("play", "Play back ROS data from a bag", _play_arguments, _play),
    Verb("record", "Record ROS data to a bag", _record_arguments, _record),
))
