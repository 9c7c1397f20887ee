"""Sweeps: one base scenario run over a grid and/or random draws of parameters, each run in its
own folder, on a local process pool or a Dask cluster, resumable, with a summary table.

    /usr/bin/python3 -m tissu.sweep SWEEP.json [--scheduler tcp://host:8786] [--workers N]

A sweep file (JSON, paths relative to it; docs/python.md "Sweeps"):

    { "scenario": "../data/scenarios/hanging_sheet.json",
      "out": "out/stiffness_sweep",
      "overrides": { "output.meshes": false, "render.enabled": false },
      "grid": { "cloth.springs.structural.stiffness": [1000, 3000, 10000] },
      "random": { "count": 4, "seed": 7,
                  "uniform": { "environment.air_damping": [0.0, 0.5] } } }

Runs are the grid's product (every combination), each repeated for every random draw when both
are given; a random draw k uses numpy's default_rng([seed, k]), so it does not depend on the
others. Run k goes to OUT/run_KKKKK: the tissu run's own files, and run.json (its parameters,
draw and seed) once it is done. A run whose run.json exists is skipped: an interrupted sweep
resumes. OUT/summary.csv has one line per run: its parameters and its last frame's stats.csv row.
"""
import argparse
import concurrent.futures
import csv
import itertools
import json
import multiprocessing
import os
import pathlib
import sys

import numpy as np

from . import load_scenario, run as run_scenario


class SweepError(ValueError):
    """A sweep file that cannot run; the message names the file and the key."""


def _key_error(file, key, expected):
    return SweepError(f"{file}: {key}: expected {expected}")


def read_sweep(path):
    """The sweep file at `path`, checked: its base scenario, output folder, overrides and the list
    of runs, each {"index", "parameters", "draw", "seed"}. Every run's scenario is loaded once
    here, so that a bad parameter path or value fails before any run starts."""
    path = pathlib.Path(path)
    try:
        spec = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as error:
        raise SweepError(f"{path}: cannot read the sweep file: {error}") from error
    if not isinstance(spec, dict):
        raise SweepError(f"{path}: expected a JSON object")
    known = {"scenario", "out", "overrides", "grid", "random"}
    for key in spec:
        if key not in known:
            raise _key_error(path, key, "one of " + ", ".join(sorted(known)) + ": unknown key")
    if not isinstance(spec.get("scenario"), str):
        raise _key_error(path, "scenario", "the path of a scenario file")
    base = (path.parent / spec["scenario"]).resolve()
    out = (path.parent / spec.get("out", f"out/{path.stem}")).resolve()
    overrides = spec.get("overrides", {})
    if not isinstance(overrides, dict):
        raise _key_error(path, "overrides", "an object {key path: value}")
    runs = _runs(path, spec.get("grid", {}), spec.get("random"))
    for run in runs:
        try:
            load_scenario(base, {**overrides, **run["parameters"]})
        except ValueError as error:
            raise SweepError(f"{path}: run {run['index']} ({run['parameters']}): {error}") from error
    return {"file": path, "scenario": base, "out": out, "overrides": overrides, "runs": runs}


def _runs(path, grid, random):
    if not isinstance(grid, dict) or not all(isinstance(v, list) and v for v in grid.values()):
        raise _key_error(path, "grid", "an object {key path: [values, ...]}")
    combinations = [dict(zip(grid, values)) for values in itertools.product(*grid.values())]
    draws = [(None, None, {})]
    if random is not None:
        if not isinstance(random, dict) or set(random) - {"count", "seed", "uniform"}:
            raise _key_error(path, "random", 'an object with "count", "seed" and "uniform"')
        count, seed, uniform = random.get("count"), random.get("seed"), random.get("uniform", {})
        if not isinstance(count, int) or count < 1:
            raise _key_error(path, "random.count", "a number of draws >= 1")
        if not isinstance(seed, int) or seed < 0:
            raise _key_error(path, "random.seed", "an integer >= 0, recorded with every run")
        for key, bounds in uniform.items():
            if not (isinstance(bounds, list) and len(bounds) == 2 and bounds[0] <= bounds[1]):
                raise _key_error(path, f"random.uniform.{key}", "[low, high] with low <= high")
        draws = []
        for k in range(count):
            rng = np.random.default_rng([seed, k])
            draws.append((k, seed, {key: float(rng.uniform(*bounds))
                                    for key, bounds in uniform.items()}))
    runs = []
    for combination in combinations:
        for draw, seed, values in draws:
            runs.append({"index": len(runs), "parameters": {**combination, **values},
                         "draw": draw, "seed": seed})
    return runs


def run_folder(sweep, run):
    return sweep["out"] / f"run_{run['index']:05d}"


def execute_run(base, overrides, run, folder):
    """One run, in a worker: the tissu run into `folder`, then run.json. Returns its summary."""
    folder = pathlib.Path(folder)
    scenario = load_scenario(base, {**overrides, **run["parameters"]})
    rows = []
    result = run_scenario(scenario, out=folder, on_frame=rows.append)
    record = {**run, "result": result, "last_frame": rows[-1]}
    done = folder / "run.json"
    temporary = done.with_suffix(".json.partial")
    temporary.write_text(json.dumps(record, indent=1))
    os.replace(temporary, done)  # whole or absent: a run is done when run.json exists
    return record


def run_sweep(sweep, executor=None, scheduler=None, workers=None, log=print):
    """Runs the sweep's runs not yet done (on `executor`, a Dask cluster at `scheduler`, or a local
    process pool of `workers`), then writes summary.csv. Returns every run's record, in order."""
    sweep["out"].mkdir(parents=True, exist_ok=True)
    pending = [run for run in sweep["runs"] if not (run_folder(sweep, run) / "run.json").exists()]
    log(f"sweep {sweep['file']}: {len(sweep['runs'])} runs, {len(pending)} to do, "
        f"into {sweep['out']}")
    arguments = [(str(sweep["scenario"]), sweep["overrides"], run, str(run_folder(sweep, run)))
                 for run in pending]
    if executor is None and scheduler is not None:
        from distributed import Client, as_completed  # Debian's python3-distributed
        with Client(scheduler) as client:
            futures = [client.submit(execute_run, *a, pure=False) for a in arguments]
            for done, future in enumerate(as_completed(futures), 1):
                future.result()
                log(f"  {done}/{len(futures)} runs done")
    else:
        own = executor is None
        # spawned, not forked: a fork of a process whose OpenMP threads exist (one that stepped a
        # cloth already) hangs in the child's first parallel region
        executor = executor or concurrent.futures.ProcessPoolExecutor(
            max_workers=workers, mp_context=multiprocessing.get_context("spawn"))
        try:
            futures = [executor.submit(execute_run, *a) for a in arguments]
            for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
                future.result()
                log(f"  {done}/{len(futures)} runs done")
        finally:
            if own:
                executor.shutdown()
    records = [json.loads((run_folder(sweep, run) / "run.json").read_text())
               for run in sweep["runs"]]
    write_summary(sweep, records)
    return records


def write_summary(sweep, records):
    parameters = list(dict.fromkeys(k for r in records for k in r["parameters"]))
    stats = list(records[0]["last_frame"]) if records else []
    with open(sweep["out"] / "summary.csv", "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["run", "draw", "seed"] + parameters + ["frames_done"] + stats)
        for r in records:
            writer.writerow([r["index"], r["draw"], r["seed"]]
                            + [r["parameters"].get(p, "") for p in parameters]
                            + [r["result"]["frames_done"]]
                            + [r["last_frame"][s] for s in stats])


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m tissu.sweep", description=__doc__.split("\n")[0])
    parser.add_argument("sweep", help="the sweep file (JSON)")
    parser.add_argument("--scheduler", help="a Dask scheduler's address (tcp://host:8786)")
    parser.add_argument("--workers", type=int, help="local processes (default: the cores)")
    options = parser.parse_args(argv)
    try:
        sweep = read_sweep(options.sweep)
        run_sweep(sweep, scheduler=options.scheduler, workers=options.workers)
    except (SweepError, ValueError, OSError, RuntimeError) as error:
        print(f"tissu sweep: {error}", file=sys.stderr)
        return 1
    print(f"tissu sweep: summary in {sweep['out'] / 'summary.csv'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
