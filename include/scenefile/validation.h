/// @file
/// The value rules of FORMATS.md, in one place. The readers call them with the
/// span of every number so that a diagnostic points at the token; a scene
/// built some other way is checked by validateScene, which points at records.
#pragma once

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

/// Largest 2-norm condition number an object matrix may have.
inline constexpr double kMaxConditionNumber = 1e12;
/// Relative tolerance under which two camera vectors count as parallel.
inline constexpr double kParallelTolerance = 1e-9;

/// A View's vertical field of view, in degrees: what the renderer renders, and
/// what every format holds and reads back (a POV-Ray camera's vectors or a
/// glTF yfov in radians stay well within a double's range).
inline constexpr double kMinFovDegrees = 0.001;
inline constexpr double kMaxFovDegrees = 179.999;
/// The longest side of an image, in pixels (a render's width and height, and
/// a conversion's): its width times its height fits an int.
inline constexpr int kMaxImageSide = 32768;
/// A View's aspect ratio (width over height): that of an image of 1 to
/// kMaxImageSide pixels a side.
inline constexpr double kMinAspectRatio = 1.0 / kMaxImageSide;
inline constexpr double kMaxAspectRatio = kMaxImageSide;

/// What a record is, for the rules that differ between them.
enum class RecordRole { Camera, Light, Object };

/// Where each value of a record stands in its file.
struct RecordSpans {
  SourceSpan record;                    ///< the record's name (or its block's START line)
  std::array<SourceSpan, 3> colour{};   ///< r, g, b
  std::array<SourceSpan, 16> matrix{};  ///< row by row, as the file writes them

  /// Every value at one place: for records that did not come from a scene file.
  static RecordSpans uniform(SourceSpan where);
  SourceSpan entry(int row, int column) const { return matrix[row * 4 + column]; }
};

/// Colours: non-negative; an object colour above 1 draws a warning. The
/// camera's colour means nothing and is not checked.
void checkColour(const glm::dvec3& colour, RecordRole role, const RecordSpans& spans,
                 DiagnosticList& out);

/// The fourth row must be exactly 0 0 0 1; says so, with the transposed-file
/// hint when the fourth column is 0 0 0 1 instead.
void checkMatrixLastRow(const glm::dmat4& matrix, const RecordSpans& spans, DiagnosticList& out);

/// An object's 3x3 block must be invertible and no worse conditioned than
/// kMaxConditionNumber. Mirrors (negative determinant) are allowed.
void checkObjectMatrix(const glm::dmat4& matrix, std::string_view what, SourceSpan where,
                       DiagnosticList& out);

/// A camera needs non-zero, non-parallel forward and up; scale or shear in its
/// matrix draws a warning, since only position, forward and up are used.
void checkCameraMatrix(const glm::dmat4& matrix, SourceSpan where, DiagnosticList& out);

/// Material ranges of FORMATS.md: [0, 1] for the five factors, SHININESS > 0,
/// RI > 0 with a warning below 1.
void checkMaterialValue(MaterialProperty property, double value, SourceSpan where,
                        DiagnosticList& out);

/// A View's field of view in [kMinFovDegrees, kMaxFovDegrees] and its aspect
/// ratio, when it has one, in [kMinAspectRatio, kMaxAspectRatio]; each value
/// outside (NaN included) is a value-out-of-range error at `where`. The one
/// rule for a view: validateScene and every writer (convertScene) hold a
/// scene's view to it, and the tools their field of view and image size.
void checkView(const View& view, SourceSpan where, DiagnosticList& out);

/// OUTPUT_FILE is one name of printable ASCII without blanks, as an
/// instruction file holds it: a name set in memory may be anything
/// (output-file-name).
void checkOutputFileName(const std::string& name, SourceSpan where, DiagnosticList& out);

/// The OUTPUT_FILE an instruction file written to `path` gets when its scene
/// has none: the file's name without its extension, with .ppm, each blank,
/// control character and character that is not ASCII made '_' ("my
/// café.txt" gives my_caf_.ppm), so that checkOutputFileName accepts it.
std::string outputFileNameFor(const std::string& path);

/// Rules about the scene as a whole: a warning when nothing is lit, and the
/// view's range (checkView).
void checkSceneLevel(const Scene& scene, DiagnosticList& out);

/// Every number of the scene is finite: camera, lights, materials, matrices,
/// LOOK_AT and transform lists. Each record holding a NaN or an infinity gets
/// one value-not-finite error at its span (at the transform for a transform
/// list); true when there is none. The readers call it last, so no accepted
/// scene holds a non-finite number, and convertScene first, so no writer is
/// ever given one.
bool checkSceneFinite(const Scene& scene, DiagnosticList& out);

/// Every rule above on a scene built in memory (by an importer, say).
DiagnosticList validateScene(const Scene& scene, std::string file = {});

}  // namespace scene
