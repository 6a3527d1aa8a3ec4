"""Exactness of the Pareto front on hand-made points."""
import math
import random
import unittest

from lpvlab_analysis.pareto import pareto_front, pareto_front_bruteforce, dominates


class ParetoTest(unittest.TestCase):
    def test_simple(self):
        pts = [(1, 10), (2, 5), (3, 6), (4, 1), (5, 1), (0.5, 20)]
        self.assertEqual(pareto_front(pts), [5, 0, 1, 3])

    def test_ties_same_time(self):
        # equal time: only the lower error survives
        self.assertEqual(pareto_front([(1, 5), (1, 3)]), [1])

    def test_ties_same_error(self):
        # equal error: only the faster survives
        self.assertEqual(pareto_front([(2, 3), (1, 3)]), [1])

    def test_duplicates(self):
        # duplicates of a front point both stay; duplicates of a dominated point both go
        pts = [(1, 2), (1, 2), (3, 3), (3, 3), (0.5, 4)]
        self.assertEqual(pareto_front(pts), [4, 0, 1])

    def test_nan_and_inf(self):
        pts = [(1, math.nan), (math.nan, 0), (2, math.inf), (3, 1), (0.5, math.inf)]
        self.assertEqual(pareto_front(pts), [4, 3])

    def test_empty_and_single(self):
        self.assertEqual(pareto_front([]), [])
        self.assertEqual(pareto_front([(1, 1)]), [0])

    def test_dominates(self):
        self.assertTrue(dominates((1, 1), (1, 2)))
        self.assertFalse(dominates((1, 1), (1, 1)))
        self.assertFalse(dominates((1, 3), (2, 2)))

    def test_matches_bruteforce(self):
        rng = random.Random(7)
        for _ in range(300):
            n = rng.randint(0, 12)
            pts = [(rng.randint(0, 4), rng.randint(0, 4)) for _ in range(n)]
            self.assertEqual(pareto_front(pts), pareto_front_bruteforce(pts), pts)


if __name__ == "__main__":
    unittest.main()
