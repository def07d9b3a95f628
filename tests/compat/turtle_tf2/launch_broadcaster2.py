"""The launch file's `broadcaster2` entry: turtle_tf2_broadcaster with turtlename turtle2."""

from turtle_tf2_broadcaster import main as broadcaster_main


def main():
    broadcaster_main(['--ros-args', '-r', '__node:=broadcaster2', '-p', 'turtlename:=turtle2'])
