"""The console around ros2: one command in the foreground, Ctrl+C, a new
command stops the last one, publishers in the background with jobs/kill."""

from __future__ import annotations

import pytest

from turtletui.graph.core import NS_PER_S
from turtletui.ros2cli import Ros2Cli, Terminal
from turtletui.ros2cli.terminal import Line
from turtletui.runtime.simulation import Simulation

PUB = "ros2 topic pub -r 10 /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: 1.0}}'"


@pytest.fixture
def sim() -> Simulation:
    return Simulation()


@pytest.fixture
def term(sim: Simulation) -> Terminal:
    return Terminal(Ros2Cli(sim))


def step(sim: Simulation, seconds: float) -> None:
    sim.run_until(sim.graph.now_ns + round(seconds * NS_PER_S))


def hidden_nodes(sim: Simulation) -> list[str]:
    return [n.fqn for n in sim.graph.nodes if n.name.startswith("_")]


def texts(lines: list[Line]) -> list[str]:
    return [line.text for line in lines]


def test_a_command_is_echoed_and_its_output_follows(term):
    out = term.run("ros2 topic list")
    assert out[0] == Line("$ ros2 topic list", "prompt")
    assert texts(out[1:]) == ["/parameter_events", "/rosout", "/turtle1/cmd_vel", "/turtle1/color_sensor", "/turtle1/pose"]
    assert term.run("ros2 topik list")[-1].kind == "error"
    assert term.run("   ") == []


def test_the_foreground_stream_prints_until_ctrl_c(sim, term):
    term.run("ros2 topic echo /turtle1/pose")
    step(sim, 0.1)  # turtlesim discovers the echo's subscription after 50 ms
    assert "---" in texts(term.poll())
    step(sim, 0.016)  # printed, not polled yet: it shows before the ^C
    stopped = term.interrupt()
    assert texts(stopped)[0] == "x: 5.544444561004639" and stopped[-1] == Line("^C", "note")
    step(sim, 0.05)
    term.run("ros2 topic echo /turtle1/pose")
    assert term.interrupt() == [Line("^C", "note")]
    assert hidden_nodes(sim) == [] and term.foreground is None
    step(sim, 0.05)
    assert term.poll() == []
    assert term.interrupt() == []  # nothing runs: nothing to say


def test_a_new_command_stops_the_last_stream_so_output_never_mixes(sim, term):
    term.run("ros2 topic hz /turtle1/pose")
    step(sim, 1.1)
    out = term.run("ros2 node list")
    assert texts(out) == ["average rate: 62.500", out[1].text, "^C", "$ ros2 node list", "/turtlesim"]
    assert hidden_nodes(sim) == []
    step(sim, 2.0)
    assert term.poll() == []


def test_a_repeating_publisher_goes_to_the_background_and_keeps_publishing(sim, term):
    term.run(PUB)
    out = term.run("ros2 topic echo /turtle1/cmd_vel --once")
    assert out[0].kind == "note" and out[0].text.startswith("[1] " + PUB)
    assert "kill %1 stops it" in out[0].text
    step(sim, 0.35)
    shown = texts(term.poll())
    assert shown[:2] == ["linear:", "  x: 1.0"]
    assert not any(text.startswith("publishing #") for text in shown)  # the job is quiet
    assert sim.world.turtles["turtle1"].vx == 1.0
    jobs = texts(term.run("jobs"))
    assert jobs[0] == "$ jobs" and jobs[1].startswith(f"[1]  Running  {PUB}  (")
    assert texts(term.run("kill %1"))[1].startswith(f"[1]  Stopped  {PUB}")
    assert term.jobs == [] and hidden_nodes(sim) == []
    count = sim.graph.topics["/turtle1/cmd_vel"].count
    step(sim, 1.0)
    assert sim.graph.topics["/turtle1/cmd_vel"].count == count


def test_an_ampersand_starts_a_publisher_in_the_background(sim, term):
    out = term.run(PUB + " &")
    assert out[-1] == Line("[1] in the background: jobs lists it, kill %1 stops it", "note")
    assert term.foreground is None and len(term.jobs) == 1
    term.run(PUB.replace("x: 1.0", "x: 2.0") + " &")
    assert [job.number for job in term.jobs] == [1, 2]
    out = term.run("kill all")
    assert [line.text.split()[1] for line in out[1:]] == ["Stopped", "Stopped"]
    assert term.jobs == [] and hidden_nodes(sim) == []


def test_only_publishers_run_in_the_background(sim, term):
    out = term.run("ros2 topic echo /turtle1/pose &")
    assert out[-1].kind == "error" and "only ros2 topic pub and ros2 bag record|play run in the background" in out[-1].text
    assert hidden_nodes(sim) == [] and term.foreground is None and term.jobs == []


def test_a_background_publisher_that_ends_says_so(sim, term):
    term.run("ros2 topic pub -r 10 -t 3 /turtle1/cmd_vel geometry_msgs/msg/Twist '{}' &")
    step(sim, 0.5)
    out = term.poll()
    assert len(out) == 1 and out[0].kind == "note" and out[0].text.startswith("[1]  Done")
    assert "(3 published)" in out[0].text and term.jobs == []


def test_kill_and_jobs_explain_their_mistakes(term):
    assert texts(term.run("jobs")) == ["$ jobs", "nothing runs in the background"]
    assert term.run("kill")[-1].kind == "error"
    assert texts(term.run("kill %3"))[-1] == "kill: %3: no such job (jobs lists them)"
    assert term.run("jobs -l")[-1].kind == "error"


def test_close_stops_everything(sim, term):
    term.run(PUB + " &")
    term.run("ros2 topic echo /turtle1/pose")
    term.close()
    assert hidden_nodes(sim) == [] and term.jobs == [] and term.foreground is None
