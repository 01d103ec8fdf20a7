"""Scene files (.sf) and instruction files (.txt) in Blender, read and
written by libscene itself through its Python module, scenefile.

File > Import > Scene file (.sf, .txt) is bpy.ops.import_scene.sf(filepath=...);
File > Export > Scene file (.sf, .txt) is bpy.ops.export_scene.sf(filepath=...,
format='SF' or 'INSTRUCTIONS'). docs/PYTHON.md is the manual.
"""

bl_info = {
    "name": "Scene file format (.sf, instruction files)",
    "author": "scenefile",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import-Export",
    "description": "Import and export scenefile's scene files and instruction files, "
                   "with their exact numbers",
    "category": "Import-Export",
}

import bpy
from bpy.props import BoolProperty, EnumProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from . import _module


def _scenefile(context):
    preferences = context.preferences.addons.get(__package__)
    folder = preferences.preferences.module_folder if preferences else ""
    return _module.load(folder)


def _scenefile_or_report(operator, context):
    """The scenefile module, or None after telling the user why it cannot be loaded."""
    try:
        return _scenefile(context)
    except ImportError as error:
        operator.report({"ERROR"}, str(error))
        return None


# The exporter's options by the settings they set (scenefile.Remedy), so
# that a hint names the option its user sees.
_OPTION_LABELS = {"approximate": "Approximate", "skip-unsupported": "Skip Unsupported"}


def _in_options(remedy):
    """A remedy as the add-on's option, else as the module's keyword."""
    return _OPTION_LABELS.get(remedy.setting, str(remedy))


def _report_diagnostics(operator, diagnostics):
    for d in diagnostics:
        level = {"error": "ERROR", "warning": "WARNING"}.get(d.severity.value, "INFO")
        hint = d.hint_in(_in_options)
        operator.report({level}, str(d) + (f" ({hint})" if hint else ""))


class ImportSceneFile(bpy.types.Operator, ImportHelper):
    """Import a scene file or an instruction file"""

    bl_idname = "import_scene.sf"
    bl_label = "Import Scene File"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".sf"
    filter_glob: StringProperty(default="*.sf;*.txt;*.pov", options={"HIDDEN"})
    skip_unsupported: BoolProperty(
        name=_OPTION_LABELS["skip-unsupported"], default=False,
        description="POV-Ray scenes: skip what the reader does not convert (CSG, other shapes, "
                    "macros, ...) with a warning, and import the rest")

    def execute(self, context):
        scenefile = _scenefile_or_report(self, context)
        if scenefile is None:
            return {"CANCELLED"}
        from . import importer
        try:
            scene = importer.import_scene(context, self.filepath, scenefile,
                                          skip_unsupported=self.skip_unsupported)
        except scenefile.SceneError as error:
            _report_diagnostics(self, error.diagnostics)
            return {"CANCELLED"}
        except OSError as error:
            self.report({"ERROR"}, f"{self.filepath}: cannot read the file: {error.strerror}")
            return {"CANCELLED"}
        _report_diagnostics(self, scene.diagnostics)
        self.report({"INFO"}, f"read {self.filepath} ({len(scene.objects)} objects, "
                              f"{len(scene.lights)} lights)")
        return {"FINISHED"}


class ExportSceneFile(bpy.types.Operator, ExportHelper):
    """Export the scene as a scene file or an instruction file"""

    bl_idname = "export_scene.sf"
    bl_label = "Export Scene File"

    filename_ext = ".sf"
    filter_glob: StringProperty(default="*.sf;*.txt", options={"HIDDEN"})
    format: EnumProperty(
        name="Format",
        items=(("SF", "Scene file (.sf)", "the camera, point lights, and each object's kind, "
                                          "colour and matrix"),
               ("INSTRUCTIONS", "Instruction file (.txt)",
                "also the Phong materials and each object's SCALE, ROTATE, TRANSLATE list")),
        default="SF")
    approximate: BoolProperty(
        name=_OPTION_LABELS["approximate"], default=False,
        description="write a matrix with shear, or a rolled camera, in an instruction file as "
                    "the nearest it can hold, instead of failing")
    use_selection: BoolProperty(name="Selected Objects", default=False,
                                description="export the selected objects only (and the camera)")

    def check(self, context):
        # In the file browser, the extension follows the format.
        base = self.filepath
        for extension in (".sf", ".txt"):
            if base.endswith(extension):
                base = base[:-len(extension)]
        path = base + (".txt" if self.format == "INSTRUCTIONS" else ".sf")
        changed = path != self.filepath
        self.filepath = path
        return changed

    def execute(self, context):
        scenefile = _scenefile_or_report(self, context)
        if scenefile is None:
            return {"CANCELLED"}
        from . import exporter
        try:
            scene, losses, notes = exporter.export_scene(
                scenefile, context, self.filepath, self.format, self.approximate,
                self.use_selection)
        except ValueError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        except scenefile.SceneError as error:
            _report_diagnostics(self, error.diagnostics)
            return {"CANCELLED"}
        except OSError as error:
            self.report({"ERROR"}, f"{self.filepath}: cannot write the file: {error.strerror}")
            return {"CANCELLED"}
        for level, message in notes:
            self.report({level}, message)
        _report_diagnostics(self, losses)
        self.report({"INFO"}, f"wrote {self.filepath} ({len(scene.objects)} objects, "
                              f"{len(scene.lights)} lights, {len(losses)} losses)")
        return {"FINISHED"}


class SceneFilePreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_folder: StringProperty(
        name="scenefile module folder", subtype="DIR_PATH", default="",
        description="the folder that holds the scenefile Python package, when it is not on "
                    "Blender's sys.path (PREFIX/lib/python3.11/dist-packages)")

    def draw(self, context):
        self.layout.prop(self, "module_folder")


def menu_import(self, context):
    self.layout.operator(ImportSceneFile.bl_idname, text="Scene File (.sf, .txt)")


def menu_export(self, context):
    self.layout.operator(ExportSceneFile.bl_idname, text="Scene File (.sf, .txt)")


CLASSES = (ImportSceneFile, ExportSceneFile, SceneFilePreferences)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)


def unregister():
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
