"""Device models: pure state and behaviour in numpy. Only emulator.window imports pygame."""

# One name for every module (docs/development.md, "One namespace"): this folder is the
# package camlab88.emulator. Imported as plain `emulator` (the repository's top on sys.path) it
# would load a second copy of every module beside the first.
if __name__ != "camlab88.emulator":
    raise ImportError(f"import camlab88.emulator, not {__name__} (is camlab88 installed?)")
