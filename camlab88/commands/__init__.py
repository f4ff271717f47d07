"""One package per area; each defines ``register(subparsers)``, the parsers built from its
``commands.toml`` (camlab88.commandspec)."""
