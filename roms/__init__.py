"""Data the devices load at power-on, in readable text formats, with loaders."""
