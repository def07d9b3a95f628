"""std_srvs: Empty, Trigger and SetBool.

Import path in ROS 2: std_srvs.srv.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'Empty',
    'SetBool',
    'Trigger',
]

Empty = _srv('std_srvs/srv/Empty', '''\
---
''', globals())

SetBool = _srv('std_srvs/srv/SetBool', '''\
bool data # e.g. for hardware enabling / disabling
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
''', globals())

Trigger = _srv('std_srvs/srv/Trigger', '''\
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
''', globals())
