"""What several programs share (not a program itself): waiting for discovery.
Python puts a script's folder on its path, so each imports it as a student
imports a module of their own beside their node."""


def spin_until(executor, condition, seconds=10.0):
    """Spin until condition() holds (discovery takes a moment under DDS)."""
    for _ in range(int(seconds / 0.05)):
        if condition():
            return True
        executor.spin_once(timeout_sec=0.05)
    return condition()
