"""Everything that crosses a wire, described once and used in both directions."""

# One name for every module (docs/development.md, "One namespace"): this folder is the
# package camlab88.protocols. Imported as plain `protocols` (the repository's top on sys.path) it
# would load a second copy of every module beside the first.
if __name__ != "camlab88.protocols":
    raise ImportError(f"import camlab88.protocols, not {__name__} (is camlab88 installed?)")
