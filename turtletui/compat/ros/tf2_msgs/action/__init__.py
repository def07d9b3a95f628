from turtletui.interfaces import ros_module_members as _members

globals().update(_members("tf2_msgs", "action"))
del _members
