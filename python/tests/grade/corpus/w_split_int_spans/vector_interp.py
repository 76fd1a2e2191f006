import numpy as np


def vector_interp(p1, p2, V1, V2, coord, dim):
    """Linear interpolation of V1 (at p1) and V2 (at p2) at x = coord (dim 1) or y = coord (dim 2)."""
    k = 0 if dim == 1 else 1
    if p1[k] == p2[k]:
        return np.array(V1, dtype=float)
    l = (p2[k] - coord) / (p2[k] - p1[k])
    return l * np.array(V1, dtype=float) + (1 - l) * np.array(V2, dtype=float)
