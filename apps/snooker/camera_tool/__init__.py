"""CCL with instant feedback (thesis §6.5: "an interactive system in which the user could
issue a command and be presented with immediate visual feedback"): the camera script beside
the live perspective view, re-interpreted on every edit."""
