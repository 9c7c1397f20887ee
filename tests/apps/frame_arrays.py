"""frames.h5 (issue 20) read back with h5py, as a user would: every frame of stats.csv is there,
with arrays that agree with it (particles, pins, total mass, kinetic energy, time), with the PC2
cache, the OBJ meshes and the glTF binaries; for a torn cloth too, whose particles change; and
the example in examples/ plots it.  usage: frame_arrays.py TISSU TINY_SCENARIO TEARING_SCENARIO EXAMPLE OUT_DIR"""
import csv, json, os, shutil, struct, subprocess, sys

import h5py
import numpy as np

tissu, tiny, tearing, example, out = sys.argv[1:6]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def run(scenario, folder, *settings):
    shutil.rmtree(folder, ignore_errors=True)
    command = [tissu, "run", scenario, "--out", folder, "--quiet", "--set", "output.arrays=true"]
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True)
    with open(os.path.join(folder, "stats.csv")) as f:
        return list(csv.DictReader(f))


def check_against_stats(folder, rows, fixed):
    with h5py.File(os.path.join(folder, "frames.h5"), "r") as h5:
        check(h5.attrs["format"] == "tissu frames 1", f"{folder}: format {h5.attrs['format']}")
        check(h5.attrs["fixed_particles"] == fixed, f"{folder}: fixed_particles")
        names = sorted(h5["frames"])
        check(names == [f"{int(r['frame']):05d}" for r in rows], f"{folder}: frames {names}")
        for row, name in zip(rows, names):
            f = h5["frames"][name]
            n = int(row["particles"])
            x, v, m = f["positions"][:], f["velocities"][:], f["masses"][:]
            where = f"{folder} frame {name}"
            check(x.shape == (n, 3) and v.shape == (n, 3) and f["rest_positions"].shape == (n, 3),
                  f"{where}: shapes {x.shape} {v.shape} for {n} particles")
            check(f["pinned"][:].sum() == int(row["pinned"]), f"{where}: pinned")
            check(abs(m.sum() - float(row["total_mass"])) <= 1e-12 * float(row["total_mass"]),
                  f"{where}: mass {m.sum()} against {row['total_mass']}")
            kinetic = 0.5 * np.sum(m * np.sum(v**2, axis=1))
            check(np.isclose(kinetic, float(row["kinetic_energy"]), rtol=1e-9, atol=1e-300),
                  f"{where}: kinetic energy {kinetic} against {row['kinetic_energy']}")
            check(np.isclose(f.attrs["time_s"], float(row["time"]), rtol=1e-12), f"{where}: time")
            triangles = f["triangles"][:]
            check(triangles.min() >= 0 and triangles.max() < n, f"{where}: triangle ids")
            check(len(triangles) >= int(row["faces"]), f"{where}: fewer triangles than faces")
        return h5["frames"][names[-1]]["positions"][:]


# a fixed cloth: the arrays match the PC2 cache and the last OBJ mesh
rows = run(tiny, f"{out}/tiny", "output.glb=true")
last = check_against_stats(f"{out}/tiny", rows, 1)
with open(f"{out}/tiny/frames.pc2", "rb") as f:
    header = f.read(32)
    points, samples = struct.unpack("<i", header[16:20])[0], struct.unpack("<i", header[28:32])[0]
    cache = np.frombuffer(f.read(), dtype="<f4").reshape(samples, points, 3)
check(np.allclose(cache[-1], last, atol=1e-6), "tiny: frames.h5 disagrees with frames.pc2")
obj = [line.split()[1:4] for line in open(f"{out}/tiny/frame_{len(rows) - 1:05d}.obj")
       if line.startswith("v ")]
check(np.allclose(np.array(obj, dtype=float), last, atol=1e-9), "tiny: disagrees with the OBJ")
# ... and the glTF binary of the same frame, y-up: (x, y, z) -> (x, z, -y)
glb = open(f"{out}/tiny/frame_{len(rows) - 1:05d}.glb", "rb").read()
json_length = struct.unpack("<I", glb[12:16])[0]
gltf = json.loads(glb[20:20 + json_length])
position = gltf["accessors"][gltf["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]
view = gltf["bufferViews"][position["bufferView"]]
start = 20 + json_length + 8 + view.get("byteOffset", 0) + position.get("byteOffset", 0)
y_up = np.frombuffer(glb[start:start + 12 * position["count"]], dtype="<f4").reshape(-1, 3)
check(np.allclose(y_up, last[:, [0, 2, 1]] * [1, 1, -1], atol=1e-6), "tiny: disagrees with the glb")

# a cloth cut at its first step: the particle count changes, every frame still agrees
rows = run(tearing, f"{out}/tearing", "simulation.frames=15", "render.enabled=false",
           "output.meshes=false")
check(rows[0]["particles"] != rows[-1]["particles"], "tearing: the particles did not change")
check_against_stats(f"{out}/tearing", rows, 0)

# the documented example plots it
subprocess.run([sys.executable, example, f"{out}/tearing"], check=True)
png = f"{out}/tearing/lowest_and_kinetic.png"
check(os.path.exists(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", "no plot written")

docs = os.path.join(os.path.dirname(example), "..", "docs", "scenario.md")
check(open(example).read() in open(docs).read(), "docs/scenario.md does not show the example as it is")

for failure in failures:
    print("FAIL:", failure)
print("ok" if not failures else f"{len(failures)} failures")
sys.exit(1 if failures else 0)
