"""Plots a run's lowest point and kinetic energy against time from its frames.h5 (a run with
--set output.arrays=true); works for runs whose particles change. usage: plot_run.py RUN_FOLDER"""
import sys
import h5py, matplotlib, numpy as np
matplotlib.use("Agg")  # writes a PNG, no display needed
import matplotlib.pyplot as plt

with h5py.File(f"{sys.argv[1]}/frames.h5", "r") as run:
    frames = [run["frames"][name] for name in sorted(run["frames"])]
    t = np.array([f.attrs["time_s"] for f in frames])
    lowest = np.array([f["positions"][:, 2].min() for f in frames])
    kinetic = np.array([0.5 * np.sum(f["masses"][:] * np.sum(f["velocities"][:] ** 2, axis=1))
                        for f in frames])
fig, (top, bottom) = plt.subplots(2, sharex=True)
top.plot(t, lowest), top.set_ylabel("lowest point z (m)")
bottom.plot(t, kinetic), bottom.set_ylabel("kinetic energy (J)"), bottom.set_xlabel("time (s)")
fig.savefig(f"{sys.argv[1]}/lowest_and_kinetic.png", dpi=100)
