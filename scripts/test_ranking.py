"""Tests bench/ranking.py's arithmetic: the mean error per method and preset, the Pareto front,
the pick within a budget, and which timed settings count as different from today's.

    python3 -m unittest discover -s scripts -p 'test_*.py'
"""
import importlib.util
import pathlib
import tempfile
import unittest

HERE = pathlib.Path(__file__).parent
spec = importlib.util.spec_from_file_location("ranking", HERE.parent / "bench" / "ranking.py")
ranking = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ranking)


def point(method, preset, cost, error):
    return {"method": method, "preset": preset, "cost": cost, "held-out": error}


class RankingTest(unittest.TestCase):
    def test_mean_rmse_averages_each_pair_over_its_views(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "metrics.csv"
            path.write_text("view,method,preset,rmse\n"
                            "a,gtao,high,0.1\nb,gtao,high,0.3\na,hbao,low,0.2\n")
            self.assertEqual(ranking.mean_rmse(path),
                             {("gtao", "high"): 0.2, ("hbao", "low"): 0.2})

    def test_front_keeps_only_pairs_no_other_beats_on_both(self):
        cheap = point("a", "low", 0.1, 0.09)
        dominated = point("b", "low", 0.2, 0.10)  # dearer and worse than `cheap`
        better = point("c", "high", 0.2, 0.06)
        tie_dearer = point("d", "ultra", 0.3, 0.06)  # as accurate as `better`, dearer
        front = ranking.pareto([dominated, tie_dearer, better, cheap])
        self.assertEqual(front, [cheap, better])

    def test_pick_is_the_most_accurate_within_budget(self):
        points = [point("a", "low", 0.1, 0.09), point("b", "high", 0.2, 0.07),
                  point("c", "ultra", 0.3, 0.05)]
        self.assertIs(ranking.pick(points, 0.2, lambda p: p["cost"]), points[1])
        self.assertIs(ranking.pick(points, 0.19, lambda p: p["cost"]), points[0])
        self.assertIs(ranking.pick(points, 1.0, lambda p: p["cost"]), points[2])

    def test_drift_names_only_what_the_method_reads(self):
        timed = {"radius": 6.0, "power": 1.1, "bent_normals": False,
                 "gtao": {"slice_count": 2}, "hbao": {"step_count": 3},
                 "spatial": {"enabled": False}}
        now = {"radius": "1", "power": "1.25", "bent_normals": "false",
               "gtao.slice_count": "1", "hbao.step_count": "4", "spatial.enabled": "true"}
        self.assertEqual(ranking.drift("gtao", timed, now),
                         ["`gtao.slice_count` 2 (now 1)", "`power` 1.1 (now 1.25)"])
        # hbao-plus runs on hbao's group.
        self.assertEqual(ranking.drift("hbao-plus", timed, now),
                         ["`hbao.step_count` 3 (now 4)", "`power` 1.1 (now 1.25)"])


if __name__ == "__main__":
    unittest.main()
