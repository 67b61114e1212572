# SPDX-License-Identifier: LGPL-2.1-or-later
"""Seeded point samplings of shapes whose feature lines are known, for the App module tests.

As the core's samplers (tests/support/SampledShapes.h) do: a grid of the given spacing over each
face's parameter domain, every sample jittered by up to +-0.2 spacing (random.Random(seed)), so
the cloud looks like a scan: roughly uniform density, no exact lattice. Shapes are centred at
the origin. Points are (x, y, z) tuples.
"""

import math
import random

JITTER = 0.2


def _grid(count, rnd):
    """Cell centres of `count` cells on [0, 1], jittered: the parameters of one grid line."""
    return [(i + 0.5 + rnd.uniform(-JITTER, JITTER)) / count for i in range(count)]


def _cells(length, spacing):
    return max(1, int(round(length / spacing)))


def plane(size, spacing, seed):
    """The square [-size/2, size/2]^2 of the plane z = 0: an open sheet."""
    rnd = random.Random(seed)
    n = _cells(size, spacing)
    return [((u - 0.5) * size, (v - 0.5) * size, 0.0)
            for u in _grid(n, rnd) for v in _grid(n, rnd)]


def _square(rnd, axis, side_sign, offset, side, spacing):
    """A square of the given side in the plane x[axis] = side_sign * offset."""
    n = _cells(side, spacing)
    points = []
    for i in range(n):
        for j in range(n):
            u = (i + 0.5 + rnd.uniform(-JITTER, JITTER)) / n
            v = (j + 0.5 + rnd.uniform(-JITTER, JITTER)) / n
            p = [0.0, 0.0, 0.0]
            p[axis] = side_sign * offset
            p[(axis + 1) % 3] = (u - 0.5) * side
            p[(axis + 2) % 3] = (v - 0.5) * side
            points.append(tuple(p))
    return points


def cube(edge, spacing, seed):
    """The surface of the cube [-edge/2, edge/2]^3: twelve sharp edges, eight corners."""
    rnd = random.Random(seed)
    points = []
    for face in range(6):
        points += _square(rnd, face // 2, 1.0 if face % 2 == 0 else -1.0, edge / 2, edge, spacing)
    return points


def capped_cylinder(radius, height, spacing, seed):
    """The closed cylinder of the given radius around the z axis, z in [-height/2, height/2]:
    the side and two flat discs, which meet at two sharp circular rims of that radius."""
    rnd = random.Random(seed)
    points = []
    around, along = _cells(2 * math.pi * radius, spacing), _cells(height, spacing)
    for i in range(around):
        phi = (i + 0.5 + rnd.uniform(-JITTER, JITTER)) / around * 2 * math.pi
        for j in range(along):
            z = ((j + 0.5 + rnd.uniform(-JITTER, JITTER)) / along - 0.5) * height
            points.append((radius * math.cos(phi), radius * math.sin(phi), z))
    n = _cells(2 * radius, spacing)
    for z in (height / 2, -height / 2):
        for u in _grid(n, rnd):
            for v in _grid(n, rnd):
                x, y = (u - 0.5) * 2 * radius, (v - 0.5) * 2 * radius
                if x * x + y * y < radius * radius:
                    points.append((x, y, z))
    return points


def rounded_cube(edge, radius, spacing, seed):
    """The cube [-edge/2, edge/2]^3 with every edge and corner rounded to `radius`: six flat
    squares (curvature 0), twelve quarter-cylinder fillets (mean curvature 1/(2 radius)) and
    eight eighth-sphere corners (1/radius), all tangent-continuous: no sharp edge."""
    rnd = random.Random(seed)
    inner = edge / 2 - radius
    side = 2 * inner
    points = []
    for face in range(6):
        points += _square(rnd, face // 2, 1.0 if face % 2 == 0 else -1.0, edge / 2, side, spacing)
    quarter = math.pi / 2
    for a in range(3):  # fillet axis
        for su in (1.0, -1.0):
            for sv in (1.0, -1.0):
                nt, nphi = _cells(side, spacing), _cells(radius * quarter, spacing)
                for i in range(nt):
                    t = ((i + 0.5 + rnd.uniform(-JITTER, JITTER)) / nt - 0.5) * side
                    for j in range(nphi):
                        phi = (j + 0.5 + rnd.uniform(-JITTER, JITTER)) / nphi * quarter
                        p = [0.0, 0.0, 0.0]
                        p[a] = t
                        p[(a + 1) % 3] = su * (inner + radius * math.cos(phi))
                        p[(a + 2) % 3] = sv * (inner + radius * math.sin(phi))
                        points.append(tuple(p))
    for sx in (1.0, -1.0):
        for sy in (1.0, -1.0):
            for sz in (1.0, -1.0):
                points += _sphere_part(rnd, (sx * inner, sy * inner, sz * inner), radius, spacing,
                                       (sx, sy, sz), quarter, quarter)
    return points


def _sphere_part(rnd, centre, radius, spacing, signs, theta_span, phi_span):
    """Rings of latitude theta in [0, theta_span] from the signed z axis, phi in [0, phi_span]
    between the signed x and y axes, each ring with as many points as its length allows."""
    points = []
    rings = _cells(radius * theta_span, spacing)
    for i in range(rings):
        theta = (i + 0.5 + rnd.uniform(-JITTER, JITTER)) / rings * theta_span
        count = _cells(radius * math.sin(theta) * phi_span, spacing)
        for j in range(count):
            phi = (j + 0.5 + rnd.uniform(-JITTER, JITTER)) / count * phi_span
            d = (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))
            points.append(tuple(c + radius * s * x for c, s, x in zip(centre, signs, d)))
    return points


def sphere(radius, spacing, seed):
    """A whole sphere: one curvature level, no edge, no boundary: no feature line at all."""
    rnd = random.Random(seed)
    return _sphere_part(rnd, (0.0, 0.0, 0.0), radius, spacing, (1.0, 1.0, 1.0), math.pi,
                        2 * math.pi)


def rounded_cube_normal(point, edge, radius):
    """The outward unit normal of rounded_cube(edge, radius, ...) at a point on it: away from
    the nearest point of the inner cube the rounding is swept around."""
    inner = edge / 2 - radius
    d = [c - max(-inner, min(inner, c)) for c in point]
    length = math.sqrt(sum(x * x for x in d))
    return tuple(x / length for x in d)


def with_normal_noise(points, normal_of, sigma, seed):
    """Every point moved along normal_of(point) by a Gaussian offset of deviation sigma, as a
    scanner's noise across the surface (random.Random(seed))."""
    rnd = random.Random(seed)
    noisy = []
    for p in points:
        n = normal_of(p)
        t = rnd.gauss(0.0, sigma)
        noisy.append((p[0] + t * n[0], p[1] + t * n[1], p[2] + t * n[2]))
    return noisy
