"""Chapter 23's sample directions in Python, for the figures that draw them
(23_sky_samples.py, 23_prefilter_samples.py): the Hammersley points and the
GGX half vector of pbr.glsl and prefilter.comp. Each figure checks that the
shader still has the lines these reproduce."""

import math


def hammersley(i: int, count: int) -> tuple[float, float]:
    bits = int(f"{i:032b}"[::-1], 2)  # bitfieldReverse
    return (i + 0.5) / count, bits * 2.3283064365386963e-10


def ggx_half_vector(i: int, count: int, alpha: float) -> tuple[float, float, float]:
    """Sample i of count: a half vector around n = (0, 0, 1), GGX-distributed."""
    u, w = hammersley(i, count)
    phi = 2.0 * math.pi * w
    cos_h = math.sqrt((1.0 - u) / (1.0 + (alpha * alpha - 1.0) * u))
    sin_h = math.sqrt(max(0.0, 1.0 - cos_h * cos_h))
    return (sin_h * math.cos(phi), sin_h * math.sin(phi), cos_h)
