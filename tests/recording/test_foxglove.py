"""`turtletui run --headless --foxglove HOST:PORT`: a minimal Foxglove WebSocket
client (the `websockets` package, subprotocol foxglove.sdk.v1) is advertised
the run's channels, receives poses, calls turtlesim's services and sets its
parameters. Messages are built and read with mcap_ros2, not turtletui."""

from __future__ import annotations

import asyncio
import json
import re
import struct
import subprocess
import sys
from pathlib import Path

import pytest
from mcap_ros2._dynamic import generate_dynamic, serialize_dynamic

pytest.importorskip("foxglove", reason="the live view needs turtletui[foxglove]")
websockets = pytest.importorskip("websockets")

from turtletui.cli.run_cmd import FOXGLOVE_DEFAULT, with_foxglove_default  # noqa: E402

SPAWN_REQUEST = "float32 x\nfloat32 y\nfloat32 theta\nstring name\n"
DEADLINE = 30.0


@pytest.fixture
def served():
    """A headless run serving Foxglove on a free port: (process, ws:// address)."""
    process = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", "--headless", "--foxglove", "127.0.0.1:0", "--duration", "60"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        url = None
        for line in process.stderr:  # log lines go to stderr, as with rclpy
            found = re.search(r"\[foxglove_bridge\]: Foxglove: open a connection to (ws://\S+)", line)
            if found:
                url = found.group(1)
                break
        assert url is not None, process.stdout.read()
        yield process, url
    finally:
        process.terminate()
        process.communicate(timeout=DEADLINE)


async def _session(url: str) -> dict:
    seen: dict = {"channels": {}, "services": {}}
    async with websockets.connect(url, subprotocols=["foxglove.sdk.v1"], max_size=None) as ws:
        assert ws.subprotocol == "foxglove.sdk.v1"

        loop = asyncio.get_running_loop()
        give_up = loop.time() + DEADLINE

        async def until(predicate, what: str):
            while True:
                try:
                    message = await asyncio.wait_for(ws.recv(), max(give_up - loop.time(), 0.01))
                except asyncio.TimeoutError:
                    raise AssertionError(f"no {what} within {DEADLINE:g} s") from None
                if isinstance(message, str):
                    data = json.loads(message)
                    if data["op"] == "serverInfo":
                        seen["info"] = data
                    elif data["op"] == "advertise":
                        seen["channels"].update({c["topic"]: c for c in data["channels"]})
                    elif data["op"] == "advertiseServices":
                        seen["services"].update({s["name"]: s for s in data["services"]})
                result = predicate(message)
                if result:
                    return result


        await until(lambda m: "/turtle1/pose" in seen["channels"] and "/spawn" in seen["services"], "pose")
        pose = seen["channels"]["/turtle1/pose"]

        def pose_data(message):
            if isinstance(message, bytes) and message[0] == 0x01 and struct.unpack_from("<I", message, 1)[0] == 7:
                return message[13:]
            if isinstance(message, str) and "Unknown channel ID" in json.loads(message).get("message", ""):
                return "again"  # foxglove-sdk can take a subscription before it lists the channel it advertised
            return None

        data = "again"
        for _ in range(5):
            await ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": 7, "channelId": pose["id"]}]}))
            data = await until(pose_data, "pose data")
            if data != "again":
                break
            await asyncio.sleep(0.2)
        decode = generate_dynamic("turtlesim/msg/Pose", pose["schema"])["turtlesim/msg/Pose"]
        seen["pose"] = decode(data)

        spawn = seen["services"]["/spawn"]
        encode = serialize_dynamic("turtlesim/msg/Spawn_Request", SPAWN_REQUEST)["turtlesim/msg/Spawn_Request"]
        payload = encode({"x": 2.0, "y": 3.0, "theta": 0.5, "name": "speedy"})
        await ws.send(struct.pack("<BIII", 0x02, spawn["id"], 42, 3) + b"cdr" + payload)

        def response(message):
            if isinstance(message, bytes) and message[0] == 0x03:
                service, call, length = struct.unpack_from("<III", message, 1)
                assert (service, call) == (spawn["id"], 42)
                return message[13 + length :]
            if isinstance(message, str) and json.loads(message)["op"] == "serviceCallFailure":
                raise AssertionError(message)
            return None

        seen["spawned"] = generate_dynamic("turtlesim/msg/Spawn_Response", "string name\n")[
            "turtlesim/msg/Spawn_Response"
        ](await until(response, "response"))

        await ws.send(json.dumps({"op": "setParameters", "id": "s", "parameters": [
            {"name": "/turtlesim.background_r", "value": 150}]}))
        await ws.send(json.dumps({"op": "getParameters", "id": "g", "parameterNames": []}))

        def parameters(message):
            if isinstance(message, str):
                data = json.loads(message)
                if data["op"] == "parameterValues" and data.get("id") == "g":
                    return {p["name"]: p["value"] for p in data["parameters"]}
            return None

        seen["parameters"] = await until(parameters, "parameters")
        await until(
            lambda m: "/speedy/pose" in seen["channels"] and "/speedy/set_pen" in seen["services"], "the new turtle"
        )
    return seen


def test_a_foxglove_client_is_advertised_the_run_and_drives_turtlesim(served):
    _, url = served
    seen = asyncio.run(_session(url))
    assert {"parameters", "services", "time"} <= set(seen["info"]["capabilities"])
    pose = seen["channels"]["/turtle1/pose"]
    assert (pose["schemaName"], pose["encoding"], pose["schemaEncoding"]) == ("turtlesim/msg/Pose", "cdr", "ros2msg")
    assert "offered_qos_profiles" in pose["metadata"]
    assert {"/tf", "/rosout", "/turtle1/cmd_vel"} <= set(seen["channels"])
    assert 0.0 < seen["pose"].x < 11.09 and 0.0 < seen["pose"].y < 11.09
    assert seen["spawned"].name == "speedy"
    assert seen["parameters"]["/turtlesim.background_r"] == 150
    assert seen["parameters"]["/turtlesim.holonomic"] is False
    assert {"/spawn", "/kill", "/clear", "/reset", "/turtle1/set_pen", "/speedy/set_pen"} <= set(seen["services"])


def test_a_bare_foxglove_flag_gets_the_default_address():
    assert with_foxglove_default(["run", "--foxglove"]) == ["run", "--foxglove", FOXGLOVE_DEFAULT]
    assert with_foxglove_default(["run", "--foxglove", "--headless"]) == [
        "run", "--foxglove", FOXGLOVE_DEFAULT, "--headless"]
    assert with_foxglove_default(["run", "--foxglove", "my_node.py"]) == [
        "run", "--foxglove", FOXGLOVE_DEFAULT, "my_node.py"]
    assert with_foxglove_default(["run", "--foxglove", "0.0.0.0:9000"]) == ["run", "--foxglove", "0.0.0.0:9000"]
    assert with_foxglove_default(["run", "--foxglove", "9000"]) == ["run", "--foxglove", "9000"]
    assert FOXGLOVE_DEFAULT.startswith("127.0.0.1:")


def test_a_bad_address_or_a_busy_port_is_a_one_line_error(served, tmp_path: Path):
    _, url = served
    busy = url.removeprefix("ws://")
    for address, words in [("nowhere:99999", "give HOST:PORT"), (busy, "cannot serve")]:
        result = subprocess.run(
            [sys.executable, "-m", "turtletui", "run", "--headless", "-d", "1", "--foxglove", address],
            capture_output=True,
            text=True,
            timeout=DEADLINE,
        )
        assert result.returncode == 2, result.stderr
        # turtlesim's start lines (on stderr, as under ROS) may come before the error
        (line,) = [x for x in result.stderr.strip().splitlines() if not re.match(r"\[(INFO|WARN)\] \[\d+\.\d+\] ", x)]
        assert result.stderr.strip().endswith(line)
        assert line.startswith("turtletui: error: --foxglove") and words in line
