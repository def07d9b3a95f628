from turtletui.compat.interface_modules import fill as _fill

_fill(globals())
del _fill
