#include "libscene/formats/instruction/instruction_writer.h"

#include <cmath>
#include <numbers>

#include "libscene/formats/object_label.h"
#include "libscene/text/number.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

void appendLine(std::string& out, int indent, std::string_view keyword,
                std::initializer_list<double> values) {
  out.append(static_cast<std::size_t>(indent) * 2, ' ');
  out += keyword;
  for (double v : values) {
    out += ' ';
    appendNumber(out, v);
  }
  out += '\n';
}

void appendVector(std::string& out, int indent, std::string_view keyword, const glm::dvec3& v) {
  appendLine(out, indent, keyword, {v.x, v.y, v.z});
}

void appendOp(std::string& out, const TransformOp& op) {
  std::string_view name = transformKindName(op.kind);
  if (op.kind == TransformKind::Scale || op.kind == TransformKind::Translate) {
    appendVector(out, 2, name, op.value);
  } else {
    appendLine(out, 2, name, {op.value.x});
  }
}

// Every matrix entry that the approximation moved, as notes.
void addMovedEntries(Diagnostic& d, const glm::dmat4& from, const glm::dmat4& to, SourceSpan span) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      if (from[c][r] == to[c][r]) continue;
      std::string message = "m";
      message += static_cast<char>('0' + r);
      message += static_cast<char>('0' + c);
      message += " moves from " + formatNumber(from[c][r]);
      message += " to " + formatNumber(to[c][r]);
      message += " (by " + formatNumber(to[c][r] - from[c][r]) + ")";
      d.notes.push_back({span, std::move(message)});
    }
  }
}

// Whether every number of the operations is finite: a decomposition's scale
// factors are column lengths, which can overflow where the entries do not.
bool opsFinite(const std::vector<TransformOp>& ops) {
  for (const TransformOp& op : ops) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(op.value[k])) return false;
    }
  }
  return true;
}

}  // namespace

std::optional<std::string> writeInstructionFile(const Scene& scene,
                                                const ConversionOptions& options,
                                                DiagnosticList& out) {
  std::size_t errorsBefore = out.errorCount();
  Severity approximationSeverity =
      options.instructions.approximate && !options.noLoss ? Severity::Warning : Severity::Error;
  // A name the reader would refuse (set in memory, or given as an option)
  // is not written.
  const std::string& outputFile =
      scene.outputFile ? *scene.outputFile : options.instructions.outputFile;
  checkOutputFileName(outputFile, scene.outputFile ? scene.outputFileSpan : SourceSpan{}, out);
  if (out.errorCount() > errorsBefore) return std::nullopt;
  std::string text;
  text += "OUTPUT_FILE ";
  text += outputFile;
  text += '\n';

  // The camera: an instruction camera keeps its LOOK_AT; any other is
  // described by one, which cannot hold a roll.
  glm::dvec3 location(scene.camera.matrix[3]);
  glm::dvec3 lookAt;
  if (scene.camera.lookAt) {
    lookAt = *scene.camera.lookAt;
  } else {
    LookAtCamera described = lookAtFromCamera(scene.camera.matrix);
    lookAt = described.lookAt;
    if (!described.expressible) {
      out.error(DiagnosticCode::ValueNotFinite, scene.camera.span,
                "the camera cannot be written as LOCATION and LOOK_AT: every point far enough "
                "along its forward axis to give that direction overflows a double")
          .hint = "the eye lies too near the largest double, looking further out";
    } else if (std::abs(described.roll) > kRollTolerance) {
      double degrees = described.roll * 180.0 / std::numbers::pi;
      bool approximate = approximationSeverity == Severity::Warning;
      Diagnostic& d = out.report(
          approximationSeverity,
          approximate ? DiagnosticCode::CameraRollApproximated : DiagnosticCode::LossCameraRoll,
          scene.camera.span,
          "the camera is rolled by " + formatNumber(degrees) +
              " degrees about its forward axis, which an instruction file cannot hold" +
              (approximate ? "; written without the roll" : ""));
      if (!approximate) {
        d.hint = "'{0}' writes the camera without its roll";
        d.remedies = {{Setting::Approximate, "true"}};
      }
    }
  }
  text += "\nSTART CAMERA\n";
  appendVector(text, 1, "LOCATION", location);
  appendVector(text, 1, "LOOK_AT", lookAt);
  text += "END CAMERA\n";

  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    if (glm::dmat3(light.matrix) != glm::dmat3(1.0)) {
      out.note(DiagnosticCode::IgnoredLightMatrix, light.span,
               "LIGHT " + std::to_string(i + 1) +
                   " is written as its position: the rest of its matrix has no meaning");
    }
    text += "\nSTART LIGHT\n";
    appendVector(text, 1, "LOCATION", light.position());
    appendVector(text, 1, "COLOUR", light.colour);
    text += "END LIGHT\n";
  }

  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    text += "\nSTART OBJECT ";
    text += objectKindName(object.kind);
    text += "\n  START MATERIAL\n";
    appendVector(text, 2, "COLOUR", object.material.colour);
    for (MaterialProperty p : kMaterialProperties) {
      appendLine(text, 2, materialPropertyName(p), {materialValue(object.material, p)});
    }
    text += "  END MATERIAL\n";

    std::vector<TransformOp> ops;
    if (object.transforms) {
      ops = *object.transforms;
    } else {
      TransformDecomposition d = decomposeTransform(object.matrix);
      if (!d.exact()) {
        bool approximate = approximationSeverity == Severity::Warning;
        Diagnostic& diag = out.report(
            approximationSeverity,
            approximate ? DiagnosticCode::MatrixApproximated : DiagnosticCode::MatrixNotExpressible,
            object.span,
            "the matrix of " + objectLabel(object, i) +
                " has shear, which SCALE, ROTATE and TRANSLATE cannot express" +
                (approximate ? "; written as the nearest rotation and scale" : ""));
        if (approximate) {
          addMovedEntries(diag, object.matrix, d.recomposed, object.span);
        } else {
          diag.hint = "'{0}' writes the nearest rotation and scale";
          diag.remedies = {{Setting::Approximate, "true"}};
        }
      }
      ops = std::move(d.ops);
      if (!opsFinite(ops)) {
        out.error(DiagnosticCode::ValueNotFinite, object.span,
                  "the matrix of " + objectLabel(object, i) +
                      " has a column longer than the largest double, which no SCALE can hold")
            .hint = "scale the scene down";
      }
    }
    text += "  START TRANSFORMATION\n";
    for (const TransformOp& op : ops) appendOp(text, op);
    text += "  END TRANSFORMATION\n";
    text += "END OBJECT\n";
  }
  if (out.errorCount() != errorsBefore) return std::nullopt;
  return text;
}

}  // namespace scene
