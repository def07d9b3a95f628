from turtletui.interfaces import ros_module_members as _members

globals().update(_members("rcl_interfaces", "srv"))
del _members
