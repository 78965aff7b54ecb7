"""The helpers every experiment script uses (experiments/scripts/experiment_common.py), against
values computed by hand. Run: PYTHONPATH=experiments/scripts /usr/bin/python3 -m unittest
tests/scripts/test_experiment_common.py (CTest: scripts.experiment_common)."""
import argparse
import math
import os
import tempfile
import unittest

import experiment_common as common


class Statistics(unittest.TestCase):
    def test_mean_sample_std_min_max(self):
        # mean 5; squared deviations 9 + 1 + 1 + 9 = 20; sample variance 20 / 3.
        s = common.stats([2.0, 4.0, 6.0, 8.0])
        self.assertEqual(s["mean"], 5.0)
        self.assertAlmostEqual(s["std"], math.sqrt(20.0 / 3.0), places=15)
        self.assertEqual((s["min"], s["max"], s["n"]), (2.0, 8.0, 4))

    def test_missing_values_are_left_out(self):
        s = common.stats([None, 1.0, math.nan, 3.0])
        self.assertEqual((s["mean"], s["n"]), (2.0, 2))
        self.assertEqual(common.stats([None])["n"], 0)
        self.assertTrue(math.isnan(common.stats([])["mean"]))

    def test_one_value_has_zero_spread(self):
        self.assertEqual(common.stats([7.5])["std"], 0.0)

    def test_median_of_odd_and_even_counts(self):
        self.assertEqual(common.median([3, 1, 2]), 2)
        self.assertEqual(common.median([4, 1, 3, 2]), 2.5)
        self.assertTrue(math.isnan(common.median([])))

    def test_mean_plus_minus_std_text(self):
        self.assertEqual(common.pm(common.stats([1.0, 3.0]), 2), "2.00 +- 1.41")
        self.assertEqual(common.pm(common.stats([])), "-")


class PathLength(unittest.TestCase):
    def test_metres_along_the_positions(self):
        # (0, 0) -> (3, 4) -> (3, 10): 5 + 6 metres; headings and the comment do not count.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "t.tum")
            with open(path, "w") as f:
                f.write("# t x y z qx qy qz qw\n0 0 0 0 0 0 0 1\n1 3 4 0 0 0 0.6 0.8\n"
                        "2 3 10 0 0 0 0 1\n")
            self.assertAlmostEqual(common.path_length(path), 11.0, places=12)


class StepMean(unittest.TestCase):
    """The best weight of a trial holds from its time until the next improvement."""

    def test_mean_and_std_of_step_functions(self):
        traces = [[(1.0, 10.0), (3.0, 4.0)], [(2.0, 8.0), (4.0, 2.0)]]
        means, stds = common.step_mean(traces, [0.5, 1.0, 2.0, 3.0, 4.0])
        # t = 0.5: no trial has a result; t = 1: one of two (< 95 %): not drawn.
        self.assertTrue(math.isnan(means[0]) and math.isnan(means[1]))
        self.assertEqual(means[2:], [9.0, 6.0, 3.0])  # (10+8)/2, (4+8)/2, (4+2)/2
        self.assertAlmostEqual(stds[2], math.sqrt(2.0), places=15)  # 1^2 + 1^2 over 1
        self.assertAlmostEqual(stds[4], math.sqrt(2.0), places=15)

    def test_one_trial_has_zero_spread(self):
        means, stds = common.step_mean([[(0.0, 5.0)]], [1.0])
        self.assertEqual((means, stds), ([5.0], [0.0]))


class Options(unittest.TestCase):
    def test_integer_at_least(self):
        at_least_one = common.integer_at_least(1)
        self.assertEqual(at_least_one("3"), 3)
        for bad in ("0", "-2", "two", "1.5"):
            with self.assertRaises(argparse.ArgumentTypeError):
                at_least_one(bad)
        self.assertEqual(common.integer_at_least(0)("0"), 0)


class Files(unittest.TestCase):
    def test_csv_round_trip(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "x.csv")
            common.write_csv(path, ["a", "b"], [[1, 0.5], ["x", ""]])
            self.assertEqual(common.read_csv(path), [{"a": "1", "b": "0.5"},
                                                     {"a": "x", "b": ""}])
            self.assertEqual(os.listdir(folder), ["x.csv"])  # no temporary file left

    def test_failed_write_keeps_the_old_file(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "table.md")
            common.write_text(path, "old")

            def fail(tmp):
                with open(tmp, "w") as f:
                    f.write("half")
                raise OSError("disk full")

            with self.assertRaises(OSError):
                common.write_atomically(path, fail)
            with open(path) as f:
                self.assertEqual(f.read(), "old")
            self.assertEqual(os.listdir(folder), ["table.md"])

    def test_optimize_files(self):
        """read_result and read_study join PREFIX.json, .trials.csv, .convergence.csv and the
        wall-clock times of PREFIX.times.json as `antslam optimize -o PREFIX` writes them."""
        with tempfile.TemporaryDirectory() as folder:
            prefix = os.path.join(folder, "p")
            common.write_text(prefix + ".json", '{"weight": {"mean": 1.5}}')
            common.write_text(prefix + ".times.json", """{"elapsed_s": {"mean": 0.2},
                "trials": [{"elapsed_s": 0.1, "time_to_best_s": 0.05,
                            "convergence": [[1, 0.01], [7, 0.04]]},
                           {"elapsed_s": 0.3, "time_to_best_s": 0.2,
                            "convergence": [[1, 0.02]]}]}""")
            common.write_text(prefix + ".trials.csv", "trial,weight\n0,1.0\n1,2.0\n")
            common.write_text(prefix + ".convergence.csv",
                              "trial,iteration,best_weight\n0,1,3.0\n0,7,1.0\n1,1,2.0\n")
            result = common.read_result(prefix)
            self.assertEqual((result["weight"]["mean"], result["elapsed_s"]["mean"]), (1.5, 0.2))
            trials, traces = common.read_study(prefix)
            self.assertEqual([(t["weight"], t["elapsed_s"]) for t in trials],
                             [("1.0", 0.1), ("2.0", 0.3)])
            self.assertEqual([[(p["best_weight"], p["elapsed_s"]) for p in trace]
                              for trace in traces],
                             [[("3.0", 0.01), ("1.0", 0.04)], [("2.0", 0.02)]])

    def test_markdown_table(self):
        self.assertEqual(common.markdown_table(["a", "b"], [[1, 2]]),
                         "| a | b |\n|---|---|\n| 1 | 2 |\n")


class Mpirun(unittest.TestCase):
    def flags(self, euid, cores, ranks):
        saved = os.geteuid, os.cpu_count
        os.geteuid, os.cpu_count = (lambda: euid), (lambda: cores)
        try:
            return common.mpirun(ranks)
        finally:
            os.geteuid, os.cpu_count = saved

    def test_root_and_oversubscription_flags_only_when_needed(self):
        self.assertEqual(self.flags(1000, 4, 2), ["mpirun", "-q", "-np", "2"])
        self.assertEqual(self.flags(0, 4, 4), ["mpirun", "-q", "-np", "4", "--allow-run-as-root"])
        self.assertEqual(self.flags(1000, 2, 3), ["mpirun", "-q", "-np", "3", "--oversubscribe"])


class RunBatch(unittest.TestCase):
    def test_one_rank_runs_the_jobs_in_order_without_mpi(self):
        with tempfile.TemporaryDirectory() as out:
            args = argparse.Namespace(ranks=1, out=out, antslam="/bin/echo")
            self.assertEqual(common.run_batch(args, [["a", 1], ["b c"]]), ["a 1\n", "b c\n"])
            self.assertEqual(os.listdir(out), [])  # no jobs file: nothing but the runs

    def test_a_job_argument_with_a_space_cannot_go_into_a_batch(self):
        with tempfile.TemporaryDirectory() as out:
            args = argparse.Namespace(ranks=2, out=out, antslam="/bin/echo")
            with self.assertRaises(SystemExit):
                common.run_batch(args, [["optimize", "my file.json"]])


if __name__ == "__main__":
    unittest.main()
