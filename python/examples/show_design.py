"""A design shown where a notebook would show it: in polyscope when it is installed, else in
matplotlib, else as a PNG rendered by curvefold itself (headless Vulkan).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/show_design.py [recording.jsonl]
"""

import struct
import sys
import zlib

import curvefold


def write_png(path, rgba):
    """A minimal PNG writer (RGBA, 8 bits), so this example needs nothing else."""
    height, width, _ = rgba.shape
    rows = b"".join(b"\x00" + rgba[y].tobytes() for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(rows)))
        out.write(chunk(b"IEND", b""))


source = sys.argv[1] if len(sys.argv) > 1 else None
design = curvefold.replay(source) if source else curvefold.Design.new("square")
if not source:
    design.fold(grab=(0.1, 0.1, 0.0), to=(0.02, 0.02, 0.08))

try:
    import polyscope

    polyscope.init()
    mesh = polyscope.register_surface_mesh("design", design.vertices, design.triangles)
    creases = design.creases()
    polyscope.register_curve_network("creases", design.vertices, creases["edges"])
    polyscope.show()
except ImportError:
    try:
        import matplotlib.pyplot as plt

        axes = plt.figure().add_subplot(projection="3d")
        v = design.vertices
        axes.plot_trisurf(v[:, 0], v[:, 1], v[:, 2], triangles=design.triangles.astype(int))
        axes.set_aspect("equal")
        plt.show()
    except ImportError:
        write_png("design.png", design.render(800, 600, view="iso", crease_pattern=True))
        print("neither polyscope nor matplotlib is installed: wrote design.png")
