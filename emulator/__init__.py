"""Device models: pure state and behaviour in numpy. Only emulator.window imports pygame."""
