"""Kept only while camlab88/commands/snooker/render.py still imports the PNG writer from
here (that file was being rewritten on another branch); everything else imports base.png.
Delete once render.py does too."""

from camlab88.base.png import frame_path, png_bytes, write_png

__all__ = ["frame_path", "png_bytes", "write_png"]
