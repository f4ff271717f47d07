"""The one PNG writer, under the name the emulator side has always imported: it lives in
base/png.py so that programs in apps/ (which never import emulator/) use it too."""

from base.png import frame_path, png_bytes, write_png

__all__ = ["frame_path", "png_bytes", "write_png"]
