"""Checks tissu's animation outputs in a real Blender (issue 20): the frame-0 OBJ imported with
tissu's axes and frames.pc2 on a Mesh Cache modifier give, at each scene frame, the positions of
that frame's OBJ; each frame's .glb, through Blender's glTF importer, gives the same points.
usage: blender -b --python scripts/check_in_blender.py -- RUN_FOLDER   (Debian: apt install blender)
The run needs frames.pc2, frame_NNNNN.obj and, for the glTF check, output.glb=true."""
import glob, os, sys

import bpy
import numpy as np

# Debian bookworm pairs Blender 3.4, whose glTF importer still uses np.bool, with numpy 1.24,
# which removed it: restore the alias for the importer (a Debian packaging issue, not tissu's)
if not hasattr(np, "bool"):
    np.bool = bool

run = sys.argv[sys.argv.index("--") + 1]
failures = []


def obj_positions(file):
    return np.array([l.split()[1:4] for l in open(file) if l.startswith("v ")], dtype=float)


def evaluated_positions(obj):
    mesh = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh()
    xyz = np.empty(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", xyz)
    return (np.array(obj.matrix_world)[:3, :3] @ xyz.reshape(-1, 3).T).T


bpy.ops.wm.read_factory_settings(use_empty=True)
# tissu's world is z-up with y forward: the importer must keep the axes as they are
bpy.ops.wm.obj_import(filepath=os.path.join(run, "frame_00000.obj"), forward_axis="Y", up_axis="Z")
cloth = bpy.context.selected_objects[0]
cache = cloth.modifiers.new("tissu", "MESH_CACHE")
cache.cache_format = "PC2"
cache.filepath = os.path.join(run, "frames.pc2")
scene = bpy.context.scene
meshes = sorted(glob.glob(os.path.join(run, "frame_*.obj")))
for file in meshes:
    frame = int(os.path.basename(file)[6:11])
    scene.frame_set(frame)
    expected, played = obj_positions(file), evaluated_positions(cloth)
    gap = np.abs(played - expected).max() if played.shape == expected.shape else np.inf
    print(f"PC2 at scene frame {frame}: largest gap {gap:.2e} m over {len(expected)} points")
    if not gap < 1e-5:
        failures.append(f"PC2 frame {frame}: gap {gap}")

for file in sorted(glob.glob(os.path.join(run, "frame_*.glb"))):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=file)
    imported = evaluated_positions(bpy.context.selected_objects[0])
    expected = obj_positions(file[:-3] + "obj")
    # the importer may reorder or split vertices: compare each imported point with its nearest
    nearest = np.array([np.abs(expected - p).sum(axis=1).min() for p in imported])
    print(f"{os.path.basename(file)}: {len(imported)} points, largest gap {nearest.max():.2e} m")
    if len(imported) < len(expected) or not nearest.max() < 1e-5:
        failures.append(f"{file}: {len(imported)} points, gap {nearest.max()}")

print("\n".join(["FAIL: " + f for f in failures]) or f"ok: {len(meshes)} frames")
sys.exit(1 if failures else 0)
