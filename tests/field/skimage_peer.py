#!/usr/bin/env python3
"""tests/field/skimage_peer.py — scikit-image's marching cubes on a raw volume,
the peer of field::marching_cubes in tests/field/skimage_peer_test.cpp.

    python3 skimage_peer.py VOLUME.f32 SIZES.json OUT.f32

VOLUME.f32: nx * ny * nz little-endian float32 values, x fastest (as
field::Grid3 stores them: values[(k * ny + j) * nx + i]).
SIZES.json: {"nx": .., "ny": .., "nz": .., "level": ..}.
OUT.f32: the vertices, 3 float32 per vertex, in (i, j, k) index space.
stdout: one line of JSON, {"vertices": V, "triangles": T, "skimage": version}.
Exit status 3 when numpy or scikit-image cannot be imported (the test skips).

The options that make skimage's vertices the same as the own core's:
  method='lorensen'       Lewiner's tables with use_classic: Lorensen and
                          Cline's cases, only grid-edge vertices (Lewiner's
                          own method adds a vertex inside some ambiguous cells);
  allow_degenerate=True   no merging of degenerate triangles' vertices, so
                          every grid-edge crossing stays one vertex;
  spacing=(1, 1, 1)       vertices stay in index space (the test maps them to
                          origin + index * spacing in double).
Its edge vertex is x0 + (w1 d1 + w2 d2) / (w1 + w2) with w = 1 / (eps + |f - c|)
and eps = 2.2e-16, i.e. t = |f0 - c| / (|f0 - c| + |f1 - c|): the same linear
interpolation as the own core's t = (c - f0) / (f1 - f0), up to rounding; a
corner is inside when f - c > 0, the own core's convention. It computes in
double and stores float32 index coordinates.

Axis order: numpy's C order makes the volume vol[k, j, i] (z, y, x) and
skimage returns vertices in that order; the script reverses the columns, so
OUT.f32 is (i, j, k) = (x, y, z).
"""
import json
import sys


def main(argv):
    if len(argv) != 4:
        print("usage: skimage_peer.py VOLUME.f32 SIZES.json OUT.f32", file=sys.stderr)
        return 2
    try:
        import numpy as np
        import skimage
        from skimage.measure import marching_cubes
    except ImportError as e:
        print("skimage_peer.py: %s (%s)" % (e, sys.executable), file=sys.stderr)
        return 3
    with open(argv[2]) as f:
        sizes = json.load(f)
    nx, ny, nz, level = int(sizes["nx"]), int(sizes["ny"]), int(sizes["nz"]), float(sizes["level"])
    vol = np.fromfile(argv[1], dtype="<f4")
    if vol.size != nx * ny * nz:
        print("skimage_peer.py: %d values, expected %d" % (vol.size, nx * ny * nz), file=sys.stderr)
        return 2
    vol = vol.reshape((nz, ny, nx))  # C order: vol[k, j, i]
    verts, faces, _normals, _values = marching_cubes(vol, level, method="lorensen",
                                                     allow_degenerate=True)
    xyz = np.ascontiguousarray(verts[:, ::-1], dtype="<f4")  # (k, j, i) -> (i, j, k)
    xyz.tofile(argv[3])
    print(json.dumps({"vertices": int(xyz.shape[0]), "triangles": int(faces.shape[0]),
                      "skimage": skimage.__version__}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
