# What the add-on tells its user: each message names its file (the file
# imported; for an export's losses the file written), and the hint that
# would cure an error names the import dialog's option, Skip Unsupported,
# which imports the rest of a POV-Ray scene.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDONS WORK EXAMPLE
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402  (sets numpy.bool before Blender's glTF code runs)

import bpy  # noqa: E402

addons, work, example = common.arguments()
addon, scenefile = common.load_addon(addons)
os.makedirs(work, exist_ok=True)
failures = common.Failures()

# The messages as the add-on reports them, kept as well as reported.
reported = []
report_diagnostics = addon._report_diagnostics


class Recorder:
    def __init__(self, operator):
        self.operator = operator

    def report(self, level, message):
        reported.append(message)
        self.operator.report(level, message)


addon._report_diagnostics = lambda operator, diagnostics: report_diagnostics(
    Recorder(operator), diagnostics)

pov = os.path.join(work, "tutorial.pov")
with open(pov, "w") as f:
    f.write("camera { location <0, 1, -5> look_at 0 }\n"
            "light_source { <0, 5, -5> color rgb 1 }\n"
            "torus { 1, 0.25 }\n"
            "sphere { 0, 1 pigment { checker rgb <1, 0, 0>, rgb 1 } }\n")

common.fresh()
result, error = common.operator(bpy.ops.import_scene.sf, filepath=pov)
failures.check(result == {"CANCELLED"}, f"the torus is refused: {result}")
failures.check(f"{pov}:3:1: error: 'torus' is not supported" in error, error)
failures.check("(Skip Unsupported converts the rest)" in error, f"the hint: {error}")

reported.clear()
result, error = common.operator(bpy.ops.import_scene.sf, filepath=pov, skip_unsupported=True)
failures.check(result == {"FINISHED"}, f"Skip Unsupported imports the rest: {result} {error}")
failures.check(len([o for o in bpy.data.objects if o.type == "MESH"]) == 1, "the sphere alone")
warnings = [m for m in reported if ": warning: " in m]
failures.check(len(warnings) == 2, f"the torus skipped, the checker's mean colour: {reported}")
failures.check(all(m.startswith(pov + ":") for m in reported), f"named: {reported}")

# A scene made in Blender has no file read: its losses name the file written.
common.fresh()
result, error = common.operator(bpy.ops.import_scene.sf, filepath=example)
reported.clear()
out = os.path.join(work, "out.sf")
result, error = common.operator(bpy.ops.export_scene.sf, filepath=out, format="SF")
failures.check(result == {"FINISHED"}, f"exported: {result} {error}")
losses = [m for m in reported if ": warning: " in m]
failures.check(losses, f"the materials a scene file drops are reported: {reported}")
failures.check(all(m.startswith(out + ":") for m in reported), f"named: {reported}")
failures.finish("the add-on's messages")
