"""The tissu Python package against the command line: the same scenario gives the same files
through tissu.run and `tissu run`, tissu.Simulation steps to the same positions, and errors
raise with the command line's messages. Run by ctest (tests/CMakeLists.txt), which sets
PYTHONPATH to the built package and TISSU_CLI, TISSU_TEST_SCENARIOS and TISSU_TEST_OUT."""
import os
import pathlib
import shutil
import subprocess
import sys
import threading
import unittest

import numpy as np

import tissu

CLI = os.environ["TISSU_CLI"]
SCENARIOS = pathlib.Path(os.environ["TISSU_TEST_SCENARIOS"])
OUT = pathlib.Path(os.environ["TISSU_TEST_OUT"])
TINY = SCENARIOS / "tiny.json"  # a 4 x 4 sheet hanging from two corners, 3 frames


def fresh(name):
    folder = OUT / name
    shutil.rmtree(folder, ignore_errors=True)
    return folder


def obj_vertices(file):
    with open(file) as lines:
        return np.array([[float(x) for x in line.split()[1:4]]
                         for line in lines if line.startswith("v ")])


class MatchesTheCommandLine(unittest.TestCase):
    def test_run_writes_the_files_the_cli_writes(self):
        cli_out, py_out = fresh("cli"), fresh("python")
        subprocess.run([CLI, "run", str(TINY), "--out", str(cli_out), "--quiet",
                        "--set", "render.enabled=false"], check=True)
        scenario = tissu.load_scenario(TINY, overrides={"render.enabled": False})
        rows = []
        result = tissu.run(scenario, out=py_out, on_frame=rows.append)
        self.assertEqual(result["frames_done"], 3)
        self.assertEqual([row["frame"] for row in rows], [0, 1, 2, 3])
        for frame in range(4):
            name = f"frame_{frame:05d}.obj"
            self.assertEqual((cli_out / name).read_bytes(), (py_out / name).read_bytes(), name)

    def test_simulation_steps_to_the_cli_positions(self):
        cli_out = fresh("cli_steps")
        subprocess.run([CLI, "run", str(TINY), "--out", str(cli_out), "--quiet",
                        "--set", "render.enabled=false"], check=True)
        sim = tissu.Simulation(tissu.load_scenario(TINY))
        start = sim.arrays()
        self.assertEqual(start["frame"], 0)
        self.assertEqual(start["positions"].shape, (25, 3))
        self.assertEqual(start["triangles"].shape[1], 3)
        self.assertEqual(int(start["pinned"].sum()), 2)
        self.assertAlmostEqual(float(start["masses"].sum()), 0.2, places=12)  # 1 m^2 at 0.2 kg/m^2
        for _ in range(3):
            sim.step()
        end = sim.arrays()
        self.assertEqual(sim.frame, 3)
        self.assertAlmostEqual(end["time_s"], 0.1, places=12)
        written = obj_vertices(cli_out / "frame_00003.obj")
        np.testing.assert_allclose(end["positions"], written, rtol=0, atol=1e-6)
        self.assertGreater(np.abs(end["velocities"]).max(), 0.0)  # it fell
        np.testing.assert_array_equal(end["rest_positions"], start["rest_positions"])

    def test_stepping_releases_the_gil(self):
        # a 60 x 60 sheet's frame in a worker thread: this thread counts while it steps. With the
        # GIL held, it could count only between the step's return and the flag's clearing, which
        # a 10 us switch interval keeps to a few counts; released, it counts all through the step
        sim = tissu.Simulation(tissu.load_scenario(TINY, overrides={
            "cloth.grid.resolution": [60, 60], "simulation.substeps": 20}))
        in_step = threading.Event()
        ticks = 0

        def step():
            in_step.set()
            sim.step()
            in_step.clear()

        interval = sys.getswitchinterval()
        sys.setswitchinterval(1e-5)
        try:
            worker = threading.Thread(target=step)
            worker.start()
            in_step.wait()  # waiting gives the worker the GIL
            while in_step.is_set():
                ticks += 1
            worker.join()
        finally:
            sys.setswitchinterval(interval)
        self.assertEqual(sim.frame, 1)
        self.assertGreater(ticks, 100000)  # about 2 million released, 2 to 20 thousand held


class ChoosesThreadsAsTheCommandLine(unittest.TestCase):
    def test_a_small_cloth_runs_on_one_thread_unless_the_scenario_says(self):
        # 25 particles: a second thread costs more than it saves (lib/thread_count.hpp), whatever
        # the machine's load; without a choice, OpenMP would give it every core
        chosen = []
        tissu.run(tissu.load_scenario(TINY, overrides={"render.enabled": False}),
                  out=fresh("threads_chosen"), on_frame=lambda row: chosen.append(row["threads"]))
        self.assertEqual(chosen, [0, 1, 1, 1])  # frame 0 has no steps
        given = []
        tissu.run(tissu.load_scenario(TINY, overrides={"render.enabled": False, "simulation.threads": 3}),
                  out=fresh("threads_given"), on_frame=lambda row: given.append(row["threads"]))
        self.assertEqual(given, [0, 3, 3, 3])

    def test_importing_sets_a_short_spin_unless_the_user_chose_a_policy(self):
        def spin_count_after_import(**policy):
            env = {k: v for k, v in os.environ.items()
                   if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
            env.update(policy)
            return subprocess.run(
                [sys.executable, "-c",
                 "import os, tissu; print(os.environ.get('GOMP_SPINCOUNT'))"],
                env=env, check=True, capture_output=True, text=True).stdout.strip()

        self.assertEqual(spin_count_after_import(), "10000")
        self.assertEqual(spin_count_after_import(OMP_WAIT_POLICY="passive"), "None")
        self.assertEqual(spin_count_after_import(GOMP_SPINCOUNT="5"), "5")


class RaisesTheCommandLinesErrors(unittest.TestCase):
    def test_a_bad_key_is_a_value_error_naming_it(self):
        with self.assertRaises(ValueError) as caught:
            tissu.load_scenario(TINY, overrides={"cloth.springs.structural.stifness": 5})
        self.assertIn("tiny.json: cloth.springs.structural.stifness: unknown key",
                      str(caught.exception))
        self.assertIn("did you mean 'stiffness'?", str(caught.exception))

    def test_a_bad_value_is_a_value_error_naming_the_range(self):
        with self.assertRaises(ValueError) as caught:
            tissu.load_scenario(TINY, overrides={"cloth.density": -3})
        self.assertIn("tiny.json: cloth.density: expected a positive number", str(caught.exception))

    def test_a_bad_pin_is_a_value_error(self):
        scenario = tissu.load_scenario(SCENARIOS / "bad_pin.json")
        with self.assertRaises(ValueError) as caught:
            tissu.Simulation(scenario)
        self.assertIn("pins[1]: vertex 999 is not a vertex", str(caught.exception))

    def test_a_step_that_diverges_raises_simulation_error(self):
        sim = tissu.Simulation(tissu.load_scenario(SCENARIOS / "exploding.json"))
        with self.assertRaises(tissu.SimulationError) as caught:
            for _ in range(200):
                sim.step()
        self.assertIn("simulation failed", "simulation failed " + str(caught.exception))
        self.assertRegex(str(caught.exception), r"^frame \d+, step 1 of 1")
        self.assertTrue(np.isfinite(sim.arrays()["positions"]).all())  # the last good state


if __name__ == "__main__":
    unittest.main()
