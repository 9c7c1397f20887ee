"""tissu from Python: load a scenario, step its cloth frame by frame with NumPy arrays, or run it
as the command line does.

    import tissu
    scenario = tissu.load_scenario("data/scenarios/hanging_sheet.json",
                                   overrides={"simulation.frames": 30})
    sim = tissu.Simulation(scenario)
    sim.step()
    a = sim.arrays()   # positions, velocities, rest_positions (n x 3, m, m/s), masses (kg),
                       # triangles (t x 3), pinned (n), frame, time_s
    tissu.run(scenario, out="out/sheet", on_frame=lambda stats: print(stats["frame"]))

Errors raise with the command line's one-line messages: ValueError for a scenario, mesh or pin
refused, tissu.SimulationError for a step that diverges, OSError for a file not written.
docs/python.md has the whole API.
"""
import json as _json
import os as _os

# libgomp's spin count, as the tissu programs set it (apps/openmp_waiting.hpp): an idle OpenMP
# thread spins about 0.1 ms, then sleeps, instead of spinning for milliseconds on cores that other
# processes (a sweep's other runs) need. libgomp reads it once, when it is loaded: set before
# _tissu loads it, and without effect if another module loaded libgomp first. A policy the user
# chose is kept.
if "OMP_WAIT_POLICY" not in _os.environ and "GOMP_SPINCOUNT" not in _os.environ:
    _os.environ["GOMP_SPINCOUNT"] = "10000"

from ._tissu import Scenario, Simulation, SimulationError  # noqa: F401
from . import _tissu

__all__ = ["Scenario", "Simulation", "SimulationError", "load_scenario", "run"]


def load_scenario(path, overrides=None):
    """The scenario in file `path`, with `overrides` {key path: value} applied as the command
    line's --set KEY=VALUE (values given as Python objects, written as JSON)."""
    sets = [f"{key}={_json.dumps(value)}" for key, value in (overrides or {}).items()]
    return _tissu.load_scenario(str(path), sets)


def run(scenario, out, frames=None, on_frame=None):
    """Runs `scenario` as `tissu run` does, writing its meshes, stats.csv and images into `out`.
    `on_frame`, if given, is called after each frame with that frame's stats.csv row as a dict.
    Returns {"frames_done", "unconverged_steps", "images", "video_warning"}."""
    return _tissu.run(scenario, str(out), frames, on_frame)
