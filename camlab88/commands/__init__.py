"""One module per area; each defines ``register(subparsers)`` and sets ``handler`` defaults."""
