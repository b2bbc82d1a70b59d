#!/usr/bin/env python3
"""check_figures_test: the smoke-test checker fails on a wrong result (a figure below its floor
or above its ceiling, a figure not printed, a failing program) and passes on a right one."""
import contextlib
import io
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_figures  # noqa: E402


def run(*args):
    with contextlib.redirect_stdout(io.StringIO()) as out:
        status = check_figures.main(list(args))
    return status, out.getvalue()


def printing(text):
    return ["--", "printf", text]


class CheckFiguresTest(unittest.TestCase):
    DOORS = "# GT lines=40\ndoors_laser: precision=0.812 recall=0.734\n"

    def test_figures_within_their_bounds_pass(self):
        status, out = run("--min", "precision=0.7", "--min", "recall=0.7", *printing(self.DOORS))
        self.assertEqual(0, status)
        self.assertIn("figures: ok", out)

    def test_a_figure_below_its_floor_fails(self):
        status, out = run("--min", "precision=0.7", "--min", "recall=0.75", *printing(self.DOORS))
        self.assertEqual(1, status)
        self.assertIn("recall=0.734 below the floor 0.75", out)

    def test_an_error_above_its_ceiling_fails(self):
        status, out = run("--max", "trans_err_m=0.05", *printing("slam x: relations=9 trans_err_m=0.0612±0.01\n"))
        self.assertEqual(1, status)
        self.assertIn("trans_err_m=0.0612 above the ceiling 0.05", out)

    def test_a_figure_not_printed_fails(self):
        status, out = run("--min", "recall_check=0.5", *printing(self.DOORS))
        self.assertEqual(1, status)
        self.assertIn("recall_check not printed", out)

    def test_the_key_must_match_whole(self):
        # precision_mean_check=0.9 is not precision_mean=…; the last line holding the key counts.
        text = "rooms: precision_mean=0.4\nrooms_split: precision_mean_check=0.9\n"
        self.assertEqual(1, run("--min", "precision_mean=0.5", *printing(text))[0])
        self.assertEqual(0, run("--min", "precision_mean=0.3", *printing(text))[0])

    def test_the_last_line_holding_the_key_counts(self):
        text = "map a: recall=0.2\nall: recall=0.9\n"
        self.assertEqual(0, run("--min", "recall=0.5", *printing(text))[0])

    def test_a_failing_program_fails_even_with_good_figures(self):
        status, out = run("--min", "recall=0.5", "--", "sh", "-c", "echo recall=0.9; exit 3")
        self.assertEqual(1, status)
        self.assertIn("status 3", out)

    def test_not_a_number_fails(self):
        self.assertEqual(1, run("--min", "recall=0.5", *printing("x: recall=nan\n"))[0])


if __name__ == "__main__":
    unittest.main()
