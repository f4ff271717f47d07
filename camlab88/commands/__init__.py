"""One package per area; each defines ``register(subparsers)``: its actions' parsers, each
declared by the action's module beside its handler (camlab88.areas)."""
