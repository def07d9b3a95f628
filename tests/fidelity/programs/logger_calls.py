"""Logger calls beyond the severity methods: log() with a severity (an enum or an int), what
each call returns (False when its level or a filter drops it), is_enabled_for, log(name=...),
the filters' argument errors, a call site whose severity changes, get_child(''), the
deprecated warn(), and an extra positional argument as print() takes it."""
import warnings

import rclpy
from rclpy.logging import LoggingSeverity
from rclpy.node import Node


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    rclpy.init()
    node = Node("caller")
    log = node.get_logger()
    print("log WARN:", log.log("through log()", LoggingSeverity.WARN))
    print("log 40:", log.log("a severity given as an int", 40))
    print("debug:", log.debug("below the level"))
    print("enabled:", [(s.name, log.is_enabled_for(s)) for s in LoggingSeverity])
    print("enabled by int:", log.is_enabled_for(20), log.is_enabled_for(10))
    attempt("severity 33:", lambda: log.log("no such severity", 33))
    attempt("is_enabled_for 7:", lambda: log.is_enabled_for(7))
    print("name=:", log.info("under another logger's name", name="elsewhere"))
    print("once:", [log.info("once", once=True) for _ in range(3)])
    print("skip_first:", [log.info("skip first", skip_first=True) for _ in range(3)])
    print("skip_first and once:", [log.info("both", skip_first=True, once=True) for _ in range(3)])
    attempt("unknown option:", lambda: log.info("x", color="red"))
    attempt("once=False:", lambda: log.info("once=False logs", once=False))
    attempt("clock not a clock:", lambda: log.info("x", throttle_duration_sec=1.0, throttle_time_source_type="steady"))
    for severity in (LoggingSeverity.INFO, LoggingSeverity.WARN):
        attempt(f"one site, {severity.name}:", lambda severity=severity: log.log("one site", severity))
    for once in (True, False):
        attempt(f"one site, once={once}:", lambda once=once: log.info("one site, filters", once=once))
    attempt("empty child:", lambda: log.get_child(""))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        print("warn:", log.warn("the deprecated alias"))
    print("warnings:", [(w.category.__name__, str(w.message)) for w in caught])
    attempt("two positionals:", lambda: log.info("speed:", 2.0))
    attempt("set_level 30:", lambda: (log.set_level(30), log.get_effective_level())[1])
    print("info at WARN:", log.info("hidden"))
    attempt("set_level 15:", lambda: log.set_level(15))
    print("level:", log.get_effective_level())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
