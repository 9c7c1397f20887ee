"""Sweeps (python/tissu/sweep.py): an 8-run sweep on a 2-worker Dask LocalCluster gives the
files of the same 8 runs made one by one; an interrupted sweep redoes only its unfinished runs;
a bad parameter fails before any run starts. Run by ctest with the environment of
test_tissu_module.py."""
import json
import os
import pathlib
import shutil
import unittest

import tissu
from tissu import sweep

SCENARIOS = pathlib.Path(os.environ["TISSU_TEST_SCENARIOS"])
OUT = pathlib.Path(os.environ["TISSU_TEST_OUT"]) / "sweep"


def sweep_file(name, **changes):
    """A sweep of tiny.json: 2 stiffnesses x 4 random air dampings (seed 3), into OUT/name."""
    spec = {"scenario": str(SCENARIOS / "tiny.json"), "out": str(OUT / name),
            "overrides": {"render.enabled": False},
            "grid": {"cloth.springs.structural.stiffness": [100, 300]},
            "random": {"count": 4, "seed": 3, "uniform": {"environment.air_damping": [0.0, 1.0]}}}
    spec.update(changes)
    shutil.rmtree(OUT / name, ignore_errors=True)
    OUT.mkdir(parents=True, exist_ok=True)
    file = OUT / f"{name}.json"
    file.write_text(json.dumps(spec))
    return file


def quiet(_):
    pass


class Sweeps(unittest.TestCase):
    def test_a_sweep_on_a_dask_cluster_gives_the_runs_made_one_by_one(self):
        from distributed import LocalCluster
        spec = sweep.read_sweep(sweep_file("dask"))
        self.assertEqual(len(spec["runs"]), 8)
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster:
            records = sweep.run_sweep(spec, scheduler=cluster.scheduler_address, log=quiet)
        self.assertEqual([r["index"] for r in records], list(range(8)))
        for run in spec["runs"]:
            alone = OUT / "alone" / f"run_{run['index']}"
            shutil.rmtree(alone, ignore_errors=True)
            tissu.run(tissu.load_scenario(spec["scenario"],
                                          {**spec["overrides"], **run["parameters"]}), out=alone)
            swept = sweep.run_folder(spec, run)
            self.assertEqual((swept / "frame_00003.obj").read_bytes(),
                             (alone / "frame_00003.obj").read_bytes(), run)
        summary = (spec["out"] / "summary.csv").read_text().splitlines()
        self.assertEqual(len(summary), 9)  # a header and 8 runs
        self.assertIn("cloth.springs.structural.stiffness", summary[0])
        # the draws are recorded, and differ
        dampings = {r["parameters"]["environment.air_damping"] for r in records}
        self.assertEqual(len(dampings), 4)
        self.assertEqual({r["seed"] for r in records}, {3})

    def test_an_interrupted_sweep_redoes_only_its_unfinished_runs(self):
        spec = sweep.read_sweep(sweep_file("resume", random=None))
        sweep.run_sweep(spec, workers=2, log=quiet)
        done = {run["index"]: (sweep.run_folder(spec, run) / "run.json").stat().st_mtime_ns
                for run in spec["runs"]}
        # as if killed during run 1: its folder has files but no run.json
        (sweep.run_folder(spec, spec["runs"][1]) / "run.json").unlink()
        lines = []
        sweep.run_sweep(spec, workers=2, log=lines.append)
        self.assertIn("2 runs, 1 to do", lines[0])
        self.assertEqual((sweep.run_folder(spec, spec["runs"][0]) / "run.json").stat().st_mtime_ns,
                         done[0])
        self.assertTrue((sweep.run_folder(spec, spec["runs"][1]) / "run.json").exists())

    def test_a_bad_parameter_fails_before_any_run_starts(self):
        file = sweep_file("bad", grid={"cloth.springs.structural.stifness": [100, 300]})
        with self.assertRaises(sweep.SweepError) as caught:
            sweep.read_sweep(file)
        self.assertIn("run 0", str(caught.exception))
        self.assertIn("did you mean 'stiffness'?", str(caught.exception))
        self.assertFalse((OUT / "bad").exists())
        file = sweep_file("bad_value", grid={"cloth.density": [0.2, -1]})
        with self.assertRaises(sweep.SweepError) as caught:
            sweep.read_sweep(file)
        self.assertIn("run 4", str(caught.exception))  # the second density, first of its 4 draws
        self.assertIn("cloth.density: expected a positive number", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
