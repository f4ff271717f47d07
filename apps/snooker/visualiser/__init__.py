"""The scene visualiser (thesis §6.3.2): a perspective view of every frame from the CCL's
viewing parameters, drawn on the Rainbow through its pad library."""
