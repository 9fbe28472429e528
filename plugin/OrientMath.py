"""Frames and rotations between Cura's scene and the engine (no Cura imports: testable outside Cura).

Cura's scene is Y-up; the engine (and the STL files the plugin hands to `mixengine orient`) is
Z-up with y pointing to the back of the printer: engine = C * scene with
C = [[1, 0, 0], [0, 0, -1], [0, 1, 0]] (x = x, y = -z, z = y; reference §4.4). A rotation R found in
the engine frame is C^T R C in the scene.
"""
import math
import struct

import numpy

SCENE_TO_ENGINE = ((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0))


def transpose(m):
    return tuple(tuple(m[j][i] for j in range(3)) for i in range(3))


def multiply(a, b):
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)) for i in range(3))


def apply(m, v):
    return tuple(sum(m[i][k] * v[k] for k in range(3)) for i in range(3))


def engineToScenePoint(p):
    return apply(transpose(SCENE_TO_ENGINE), p)


def engineToSceneRotation(rotation):
    """The scene-frame rotation of an engine-frame rotation matrix (rows)."""
    c = SCENE_TO_ENGINE
    return multiply(transpose(c), multiply(rotation, c))


def isRotation(m, tolerance=1e-4):
    """Orthonormal with determinant +1, within tolerance."""
    identity = multiply(m, transpose(m))
    for i in range(3):
        for j in range(3):
            if abs(identity[i][j] - (1.0 if i == j else 0.0)) > tolerance:
                return False
    det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return abs(det - 1.0) <= tolerance


def quaternionFromMatrix(m):
    """(x, y, z, w), unit length, of a rotation matrix (rows), picking the numerically largest
    component first so that no division by a small number occurs."""
    trace = m[0][0] + m[1][1] + m[2][2]
    candidates = (trace, m[0][0], m[1][1], m[2][2])
    largest = max(range(4), key=lambda i: candidates[i])
    if largest == 0:
        s = math.sqrt(1.0 + trace) * 2
        q = ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4)
    elif largest == 1:
        s = math.sqrt(max(0.0, 1.0 + m[0][0] - m[1][1] - m[2][2])) * 2
        q = (s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s)
    elif largest == 2:
        s = math.sqrt(max(0.0, 1.0 + m[1][1] - m[0][0] - m[2][2])) * 2
        q = ((m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s)
    else:
        s = math.sqrt(max(0.0, 1.0 + m[2][2] - m[0][0] - m[1][1])) * 2
        q = ((m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4, (m[1][0] - m[0][1]) / s)
    norm = math.sqrt(sum(c * c for c in q))
    return tuple(c / norm for c in q)


def translationAfterRotation(rotation, centre):
    """t such that R p + t = c + R (p - c): what a rotation about the origin must be moved by to
    be a rotation about `centre`."""
    rc = apply(rotation, centre)
    return tuple(centre[i] - rc[i] for i in range(3))


_STL_FACET = numpy.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])


def binaryStl(corners, header=b"MixEngine orientation part"):
    """Binary STL bytes of an (N*3, 3) array of triangle corners in mm (3 rows per facet).
    Normals are left zero; STL readers (MixEngine's included) recompute them."""
    corners = numpy.asarray(corners, dtype=numpy.float32).reshape(-1, 3, 3)
    facets = numpy.zeros(len(corners), dtype=_STL_FACET)
    facets["corners"] = corners
    return header[:80].ljust(80, b"\0") + struct.pack("<I", len(corners)) + facets.tobytes()

