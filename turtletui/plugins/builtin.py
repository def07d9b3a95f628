"""The built-in plugin: the course's reference controllers, bundled lessons
and worlds. (The grading engine's checks are another built-in plugin,
turtletui.grading.builtin_checks.)
"""

from __future__ import annotations

from turtletui.plugins import hookimpl
from turtletui.plugins.bundled import lessons_dir, reference_dir
from turtletui.plugins.hookspecs import RegisterController, RegisterLesson, RegisterWorld

REFERENCE_CONTROLLERS: tuple[tuple[str, str, str], ...] = (
    (
        "part3_first_node",
        "my_first_node.py",
        "Part 3: a first node that logs a counter from a timer",
    ),
    ("part4_draw_circle", "draw_circle.py", "Part 4: publishes cmd_vel so turtle1 draws a circle"),
    (
        "part5_pose_subscriber",
        "pose_subscriber.py",
        "Part 5: subscribes to turtle1's pose and logs it",
    ),
    (
        "part6_wall_avoider",
        "turtle_controller.py",
        "Part 6: closed-loop control that turns away from walls",
    ),
    (
        "part7_pen_color",
        "turtle_controller_pen.py",
        "Part 7: the wall avoider, changing pen colour through a service",
    ),
    ("go_to_goal", "go_to_goal.py", "Drives turtle1 to (goal_x, goal_y) with a P controller and stops"),
    (
        "rotate_action_client",
        "rotate_action_client.py",
        "Turns turtle1 north, west, south, east with rotate_absolute action goals",
    ),
    (
        "parameters_wall_avoider",
        "parameters_wall_avoider.py",
        "The Part 6 wall avoider with its speeds, turn rate and box as node parameters",
    ),
    (
        "turtle_chaser",
        "turtle_chaser.py",
        "Spawns turtles, chases each with turtle1 and kills it when caught",
    ),
    (
        "lidar_obstacle_avoider",
        "lidar_obstacle_avoider.py",
        "Reads the front of /turtle1/scan and turns toward the more open side",
    ),
    (
        "tf2_buffer_server",
        "tf2_buffer_server.py",
        "tf2_ros's buffer_server: answers tf2_ros.BufferClient's lookups on tf2_buffer_server",
    ),
)
"""(controller name, file in the reference folder, description)."""


@hookimpl
def turtletui_register_controllers(register: RegisterController) -> None:
    folder = reference_dir()
    for name, filename, description in REFERENCE_CONTROLLERS:
        register(name, folder / filename, description)


@hookimpl
def turtletui_register_lessons(register: RegisterLesson) -> None:
    folder = lessons_dir()
    if folder is not None:
        register(folder)


BUNDLED_WORLDS: tuple[tuple[str, str, str], ...] = (
    (
        "lidar-course",
        "lidar_course.toml",
        "Circles and boxes to roam among, with a 360-degree LiDAR on /<turtle>/scan",
    ),
)
"""(world name, file in lessons/worlds, description)."""


@hookimpl
def turtletui_register_worlds(register: RegisterWorld) -> None:
    # Factories return what turtletui.worlds reads (here a file's path): this
    # layer is below turtletui.worlds and must not import it. "empty" is
    # built into turtletui.worlds itself.
    folder = lessons_dir()
    if folder is None:
        return
    for name, filename, description in BUNDLED_WORLDS:
        path = folder / "worlds" / filename
        register(name, lambda path=path: path, description)
