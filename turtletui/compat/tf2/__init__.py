"""tf2 for controllers: tf2's BufferCore (frames, time caches, lookups) and
tf2_ros's Buffer, TransformListener and broadcasters, written from tf2's
sources (buffer_core.cpp, cache.cpp, tf2_ros_py) and exposed to controllers as
``tf2_py`` and ``tf2_ros`` by the packages in ``turtletui/compat/ros``."""
