// The comments that carry the exact scene in an OBJ (docs/OBJ.md,
// "Comments"): what OBJ has no statement for (the camera, the lights, the
// view, OUTPUT_FILE) and each object's kind, matrix, material and
// operations, which its mesh and MTL material only approximate. Every
// other program skips comments; the OBJ reader believes an object's
// comment only while its mesh and material are still what the comment
// writes (obj_reader.h).
//
// One comment a line, after the prefix kObjExactComment:
//   camera matrix <16 numbers, row by row> colour r g b [look_at x y z]
//   view fov F [aspect A]
//   output_file NAME            (the rest of the line)
//   light matrix <16 numbers> colour r g b
//   object KIND segments N plane_size H matrix <16 numbers>
//          material r g b AMBIENT DIFFUSE SPECULAR SHININESS REFLECTIVITY
//          TRANSPARENCY RI [transforms SCALE x y z ROTATE_X a ...]
// The object's comment stands right before its `o` line.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenefile/scene.h"

namespace scene {

inline constexpr std::string_view kObjExactComment = "# scenefile";

// An object as its comment describes it, with what its mesh was made from.
struct ObjectComment {
  Object object;
  int segments = 0;
  float planeHalfSize = 1.0f;
};

// The comment lines of what OBJ has no statement for, each ending in '\n'.
std::string sceneComments(const Scene& scene);
// The comment line of one object, ending in '\n'.
std::string objectComment(const ObjectComment& comment);

// What the scene comments of a file said, as far as they read cleanly.
struct SceneComments {
  std::optional<Camera> camera;
  std::optional<View> view;
  std::optional<std::string> outputFile;
  std::vector<Light> lights;
};

// Reads one comment's words (its text after the prefix) into `scene`, or
// for an object's comment into `object`; false when they are no comment of
// ours or do not read cleanly (the comment is then ignored).
bool readComment(std::string_view words, SceneComments& scene,
                 std::optional<ObjectComment>& object);

}  // namespace scene
