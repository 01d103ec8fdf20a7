"""Sets a window of an EXR file's header (a box2i: x and y min, x and y max),
as a hostile file sets it: exr_window.py IN WINDOW OUT XMIN YMIN XMAX YMAX."""
import struct
import sys

path, name, out = sys.argv[1], sys.argv[2].encode(), sys.argv[3]
data = bytearray(open(path, "rb").read())
key = name + b"\0box2i\0"
at = data.index(key) + len(key) + 4
data[at:at + 16] = struct.pack("<4i", *map(int, sys.argv[4:8]))
open(out, "wb").write(data)
