// The POV-Ray 3.7 writer: a scene that POV-Ray renders as the renderer does.
//
// Geometry is exact: each object is its unit primitive under its own 4x4, and
// the camera's vectors are those of the renderer's pinhole. Numbers are
// written in their shortest exact form. What POV-Ray's syntax cannot hold bit for bit
// (the camera's matrix and colour, a light's matrix) rides in comments of the
// form `<kPovExactComment> ...`, which POV-Ray ignores and pov_reader.h
// reads back.
// docs/POVRAY.md has every mapping decision.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "libscene/formats/pov/pov_lexer.h"
#include "scenefile/convert.h"
#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

// The comments that carry exact values, one a line:
//   <kPovExactComment> camera matrix <16 numbers, row by row> colour r g b [look_at x y z]
//                      fov F width W height H      (on the same line)
//   <kPovExactComment> light matrix <16 numbers>
//   <kPovExactComment> object [last_row 0 -0 0 1] [transforms SCALE x y z ROTATE_X a ...]
//   <kPovExactComment> output_file NAME
// each just before the statement it belongs to (output_file anywhere).
// kPovExactComment (pov_lexer.h) is the prefix.

// The scene in POV-Ray's scene language, or nothing when `noLoss` forbids a
// loss. Each value that POV-Ray cannot render as the renderer does is
// reported in `out` at its object [pov-write-loss].
std::optional<std::string> writePovScene(const Scene& scene, const ConversionOptions& options,
                                         DiagnosticList& out);

// The 8-bit colour that a flat export gives object `index` of `count`: each
// channel a multiple of 17 while count < 4096 (so that a rounding of up to
// 8 levels cannot confuse two objects), any byte beyond. Neighbouring objects
// get far-apart colours.
std::array<int, 3> povFlatColour(std::size_t index, std::size_t count);

// The object whose flat colour `rgb` is (its index), -1 for black (nothing
// hit), or nothing when the colour is no object's.
std::optional<long long> povFlatObject(const std::array<int, 3>& rgb, std::size_t count);

}  // namespace scene
