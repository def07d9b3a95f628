"""The launch file's `broadcaster1` entry: turtle_tf2_broadcaster with turtlename turtle1."""

from turtle_tf2_broadcaster import main as broadcaster_main


def main():
    broadcaster_main(['--ros-args', '-r', '__node:=broadcaster1', '-p', 'turtlename:=turtle1'])
