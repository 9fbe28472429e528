"""The triangle soup Cura sends for a model: little-endian float32 x, y, z, nine per triangle, read from
a binary or ASCII STL. Standard library only: used both by the venv's tests and by cura_frontend.py,
which runs on Debian's /usr/bin/python3."""
import struct


def triangle_soup_bytes(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:5] == b"solid" and b"facet" in data[:1000]:
        words = data.decode("ascii").split()
        values = [float(words[i + j]) for i, w in enumerate(words) if w == "vertex" for j in (1, 2, 3)]
        return struct.pack("<%df" % len(values), *values)
    (count,) = struct.unpack_from("<I", data, 80)
    return b"".join(data[84 + i * 50 + 12:84 + i * 50 + 48] for i in range(count))
