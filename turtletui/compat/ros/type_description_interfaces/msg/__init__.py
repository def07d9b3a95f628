from turtletui.interfaces import ros_module_members as _members

globals().update(_members("type_description_interfaces", "msg"))
del _members
