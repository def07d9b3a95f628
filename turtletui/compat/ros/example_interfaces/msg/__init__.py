from turtletui.interfaces import ros_module_members as _members

globals().update(_members("example_interfaces", "msg"))
del _members
