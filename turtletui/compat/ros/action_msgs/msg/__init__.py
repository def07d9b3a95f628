from turtletui.interfaces import ros_module_members as _members

globals().update(_members("action_msgs", "msg"))
del _members
