"""The interactive snooker motion-development program on the Rainbow (thesis §6.2.1-§6.2.2).

Pure interaction state and geometry (layout, arrows, menus' item lists, scripted input) are
kept apart from the drawing, which goes only through ``camlab88.protocols.rainbow``.
"""
