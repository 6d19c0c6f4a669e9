"""The median of paired ratios and its distribution-free interval, shared by the tools that pair renders round by round
(`many-cores.py`, `thread-speedup.py`)."""
import math


def median_interval(values, level=0.95):
    """A distribution-free interval for the median: the order statistics k and n + 1 − k (1-based) of n values, with k
    the largest for which P(Binomial(n, ½) < k) ≤ (1 − level) / 2; None when n is too small for the level."""
    v, n = sorted(values), len(values)
    k, below = 0, 0.0
    while True:
        nxt = below + math.comb(n, k) / 2 ** n
        if nxt > (1 - level) / 2:
            break
        below, k = nxt, k + 1
    return (v[k - 1], v[n - k]) if k >= 1 else None
