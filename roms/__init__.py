"""Data the devices load at power-on, in readable text formats, with loaders."""

# One name for every module (docs/development.md, "One namespace"): this folder is the
# package camlab88.roms. Imported as plain `roms` (the repository's top on sys.path) it
# would load a second copy of every module beside the first.
if __name__ != "camlab88.roms":
    raise ImportError(f"import camlab88.roms, not {__name__} (is camlab88 installed?)")
