"""Rigid transforms as tf2 stores them: a translation and a unit quaternion
(x, y, z, w), with the products, inverses and slerp tf2's LinearMath uses."""

from __future__ import annotations

import math
import sys
from typing import NamedTuple

Vec = tuple[float, float, float]
Quat = tuple[float, float, float, float]

IDENTITY_QUAT: Quat = (0.0, 0.0, 0.0, 1.0)
ZERO: Vec = (0.0, 0.0, 0.0)


class Stored(NamedTuple):
    """One transform in a frame's cache: the child frame in its parent at ``stamp_ns``."""

    stamp_ns: int
    parent: str
    translation: Vec
    rotation: Quat


def multiply(a: Quat, b: Quat) -> Quat:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by + ay * bw + az * bx - ax * bz,
        aw * bz + az * bw + ax * by - ay * bx,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def inverse(q: Quat) -> Quat:
    x, y, z, w = q
    n = x * x + y * y + z * z + w * w
    return (-x / n, -y / n, -z / n, w / n)


def rotate(q: Quat, v: Vec) -> Vec:
    """``v`` rotated by ``q`` (tf2's quatRotate: q * v * q^-1)."""
    x, y, z, _ = multiply(multiply(q, (v[0], v[1], v[2], 0.0)), inverse(q))
    return (x, y, z)


def add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def negate(v: Vec) -> Vec:
    return (-v[0], -v[1], -v[2])


def lerp(a: Vec, b: Vec, ratio: float) -> Vec:
    return tuple(p + (q - p) * ratio for p, q in zip(a, b, strict=True))  # type: ignore[return-value]


def slerp(a: Quat, b: Quat, ratio: float) -> Quat:
    """Spherical interpolation from ``a`` to ``b`` along the shorter arc
    (tf2's Quaternion::slerp: nearly equal quaternions give ``a``)."""
    magnitude = math.sqrt(sum(p * p for p in a) * sum(q * q for q in b))
    product = sum(p * q for p, q in zip(a, b, strict=True)) / magnitude
    if abs(product) >= 1.0 - sys.float_info.epsilon:  # TF2SIMD_EPSILON for doubles
        return a
    theta = math.acos(abs(product))
    d = math.sin(theta)
    sign = -1.0 if product < 0 else 1.0
    s0 = math.sin((1.0 - ratio) * theta) / d
    s1 = math.sin(sign * ratio * theta) / d
    return tuple(p * s0 + q * s1 for p, q in zip(a, b, strict=True))  # type: ignore[return-value]


def compose(outer_t: Vec, outer_q: Quat, inner_t: Vec, inner_q: Quat) -> tuple[Vec, Quat]:
    """The transform ``outer * inner`` (inner applied first)."""
    return add(rotate(outer_q, inner_t), outer_t), multiply(outer_q, inner_q)


def invert(t: Vec, q: Quat) -> tuple[Vec, Quat]:
    inv_q = inverse(q)
    return rotate(inv_q, negate(t)), inv_q
