"""Exact Pareto front of (time, error) points, both minimised.

Used to mark the configurations worth considering in the speed/accuracy
plot: a configuration is on the front when no other one is at least as fast
and at least as accurate while being strictly better in one of the two.

Conventions (tested in tests/test_pareto.py):
  * points with a NaN coordinate are never on the front and never dominate;
  * +inf is an ordinary (worst) value, so (t, inf) can be on the front only
    when nothing else is as fast;
  * exact duplicates of a non-dominated point are all on the front (they are
    equally optimal); duplicates of a dominated point are all dominated.
"""
import math


def dominates(a, b):
    """True when point a=(time, error) Pareto-dominates point b (minimising both)."""
    return a[0] <= b[0] and a[1] <= b[1] and (a[0] < b[0] or a[1] < b[1])


def pareto_front(points):
    """Indices of the non-dominated points, ordered by increasing time (then index).

    points: sequence of (time, error) pairs. O(n log n): sort by (time, error)
    and keep each point whose error is strictly below every error seen so far,
    or which equals the previous front point exactly.
    """
    valid = []
    for i, (t, e) in enumerate(points):
        t, e = float(t), float(e)
        if math.isnan(t) or math.isnan(e):
            continue
        valid.append((t, e, i))
    valid.sort()
    front = []
    best = None
    last = None
    for t, e, i in valid:
        if best is None or e < best:
            front.append(i)
            best = e
            last = (t, e)
        elif (t, e) == last:
            front.append(i)
    return front


def pareto_front_bruteforce(points):
    """O(n^2) reference implementation of pareto_front (same conventions), for tests."""
    pts = [(float(t), float(e)) for t, e in points]
    ok = [i for i, p in enumerate(pts) if not (math.isnan(p[0]) or math.isnan(p[1]))]
    front = [i for i in ok if not any(dominates(pts[j], pts[i]) for j in ok if j != i)]
    return sorted(front, key=lambda i: (pts[i][0], pts[i][1], i))
