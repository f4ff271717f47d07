"""camlab88: the command-line entry point and the glue that wires programs to devices."""

__version__ = "0.1.0"
