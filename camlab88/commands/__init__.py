"""One package per command: an area lists its actions' modules (``ACTIONS``), a single
command declares itself in its ``__init__``; every command module has the one shape
camlab88.areas describes (``HELP``, ``add_arguments``, ``run``)."""
