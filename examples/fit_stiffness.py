#!/usr/bin/python3
"""Fits the structural stiffness of Liu et al.'s hanging sheet (data/scenarios/hanging_sheet.json,
on a 20 x 20 grid) so that it hangs 1.01 m below its pins, as a measured sag would say, with
SciPy's bounded scalar minimiser over log10(k) and tissu's Python package (docs/python.md).
From the project's root, after the build:
    PYTHONPATH=build/release/python /usr/bin/python3 examples/fit_stiffness.py"""
import time
from scipy.optimize import minimize_scalar
import tissu

TARGET_SAG_M = 1.01  # the measured drop of the sheet's lowest point below its pins, at rest

def sag_m(stiffness):
    """The sheet's drop below its pins after 4 s, with air damping to settle it (m)."""
    scenario = tissu.load_scenario("data/scenarios/hanging_sheet.json", overrides={
        "cloth.grid.resolution": [20, 20], "cloth.springs.structural.stiffness": stiffness,
        "environment.air_damping": 2.0, "simulation.frames": 120})
    sim = tissu.Simulation(scenario)
    pins_z = sim.arrays()["positions"][sim.arrays()["pinned"] == 1, 2].mean()
    for _ in range(scenario.frames):
        sim.step()
    return pins_z - sim.arrays()["positions"][:, 2].min()

start = time.time()
fit = minimize_scalar(lambda log_k: (sag_m(10 ** log_k) - TARGET_SAG_M) ** 2,
                      bounds=(1, 5), method="bounded", options={"xatol": 1e-4})
k = 10 ** fit.x
print(f"structural stiffness {k:.0f} N/m: sag {sag_m(k):.4f} m "
      f"({fit.nfev} runs, {time.time() - start:.1f} s)")
