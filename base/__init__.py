"""Small pieces every layer uses that cross no wire.

Atomic files, kernel loading and its notices, PNG, text input, did-you-mean.
"""

# One name for every module (docs/development.md, "One namespace"): this folder is the
# package camlab88.base. Imported as plain `base` (the repository's top on sys.path) it
# would load a second copy of every module beside the first.
if __name__ != "camlab88.base":
    raise ImportError(f"import camlab88.base, not {__name__} (is camlab88 installed?)")
