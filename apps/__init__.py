"""The 1980s programs.

They talk to devices only through protocols/ (never emulator/, never pygame).
"""

# One name for every module (docs/development.md, "One namespace"): this folder is the
# package camlab88.apps. Imported as plain `apps` (the repository's top on sys.path) it
# would load a second copy of every module beside the first.
if __name__ != "camlab88.apps":
    raise ImportError(f"import camlab88.apps, not {__name__} (is camlab88 installed?)")
