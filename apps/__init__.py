"""The 1980s programs.

They talk to devices only through protocols/ (never emulator/, never pygame).
"""
