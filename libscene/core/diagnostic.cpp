#include "scenefile/diagnostic.h"

#include <array>
#include <utility>

namespace scene {

std::string_view severityName(Severity severity) {
  switch (severity) {
    case Severity::Note:
      return "note";
    case Severity::Warning:
      return "warning";
    case Severity::Error:
      return "error";
  }
  return "error";
}

namespace {

struct CodeEntry {
  DiagnosticCode code;
  std::string_view name;
};

constexpr std::array kCodes = {
    CodeEntry{DiagnosticCode::InvalidByte, "invalid-byte"},
    CodeEntry{DiagnosticCode::InvalidNumber, "invalid-number"},
    CodeEntry{DiagnosticCode::NumberOutOfRange, "number-out-of-range"},
    CodeEntry{DiagnosticCode::CommentNotAllowed, "comment-not-allowed"},
    CodeEntry{DiagnosticCode::UnknownKeyword, "unknown-keyword"},
    CodeEntry{DiagnosticCode::TokenCount, "token-count"},
    CodeEntry{DiagnosticCode::UnknownFormat, "unknown-format"},
    CodeEntry{DiagnosticCode::MissingCamera, "missing-camera"},
    CodeEntry{DiagnosticCode::CameraNotFirst, "camera-not-first"},
    CodeEntry{DiagnosticCode::DuplicateCamera, "duplicate-camera"},
    CodeEntry{DiagnosticCode::TruncatedRecord, "truncated-record"},
    CodeEntry{DiagnosticCode::BlankLineInRecord, "blank-line-in-record"},
    CodeEntry{DiagnosticCode::ExpectedRecordName, "expected-record-name"},
    CodeEntry{DiagnosticCode::MatrixLastRow, "matrix-last-row"},
    CodeEntry{DiagnosticCode::MatrixSingular, "matrix-singular"},
    CodeEntry{DiagnosticCode::MatrixIllConditioned, "matrix-ill-conditioned"},
    CodeEntry{DiagnosticCode::NegativeColour, "negative-colour"},
    CodeEntry{DiagnosticCode::ColourAboveOne, "colour-above-one"},
    CodeEntry{DiagnosticCode::CameraDegenerate, "camera-degenerate"},
    CodeEntry{DiagnosticCode::CameraScaled, "camera-scaled"},
    CodeEntry{DiagnosticCode::NoLight, "no-light"},
    CodeEntry{DiagnosticCode::ValueOutOfRange, "value-out-of-range"},
    CodeEntry{DiagnosticCode::RiBelowOne, "ri-below-one"},
    CodeEntry{DiagnosticCode::ZeroScale, "zero-scale"},
    CodeEntry{DiagnosticCode::MissingOutputFile, "missing-output-file"},
    CodeEntry{DiagnosticCode::OutputFileName, "output-file-name"},
    CodeEntry{DiagnosticCode::OutputFileEscapes, "output-file-escapes"},
    CodeEntry{DiagnosticCode::UnexpectedLine, "unexpected-line"},
    CodeEntry{DiagnosticCode::UnclosedBlock, "unclosed-block"},
    CodeEntry{DiagnosticCode::MismatchedEnd, "mismatched-end"},
    CodeEntry{DiagnosticCode::UnexpectedEnd, "unexpected-end"},
    CodeEntry{DiagnosticCode::DuplicateProperty, "duplicate-property"},
    CodeEntry{DiagnosticCode::MissingProperty, "missing-property"},
    CodeEntry{DiagnosticCode::DuplicateSection, "duplicate-section"},
    CodeEntry{DiagnosticCode::UnknownObjectKind, "unknown-object-kind"},
    CodeEntry{DiagnosticCode::CameraLookAtLocation, "camera-look-at-location"},
    CodeEntry{DiagnosticCode::LossMaterial, "loss-material"},
    CodeEntry{DiagnosticCode::LossCameraRoll, "loss-camera-roll"},
    CodeEntry{DiagnosticCode::MatrixNotExpressible, "matrix-not-expressible"},
    CodeEntry{DiagnosticCode::MatrixApproximated, "matrix-approximated"},
    CodeEntry{DiagnosticCode::CameraRollApproximated, "camera-roll-approximated"},
    CodeEntry{DiagnosticCode::DroppedOutputFile, "dropped-output-file"},
    CodeEntry{DiagnosticCode::IgnoredLightMatrix, "ignored-light-matrix"},
    CodeEntry{DiagnosticCode::TooManyErrors, "too-many-errors"},
    CodeEntry{DiagnosticCode::PlaneMadeFinite, "plane-made-finite"},
    CodeEntry{DiagnosticCode::LightFalloff, "light-falloff"},
    CodeEntry{DiagnosticCode::GltfValueClamped, "gltf-value-clamped"},
    CodeEntry{DiagnosticCode::GltfExtrasOnly, "gltf-extras-only"},
    CodeEntry{DiagnosticCode::GltfMatrixSplit, "gltf-matrix-split"},
    CodeEntry{DiagnosticCode::GltfInvalidJson, "gltf-invalid-json"},
    CodeEntry{DiagnosticCode::GltfInvalidGlb, "gltf-invalid-glb"},
    CodeEntry{DiagnosticCode::GltfInvalid, "gltf-invalid"},
    CodeEntry{DiagnosticCode::GltfIndexOutOfRange, "gltf-index-out-of-range"},
    CodeEntry{DiagnosticCode::GltfBadAccessor, "gltf-bad-accessor"},
    CodeEntry{DiagnosticCode::GltfExternalFile, "gltf-external-file"},
    CodeEntry{DiagnosticCode::GltfNodeCycle, "gltf-node-cycle"},
    CodeEntry{DiagnosticCode::GltfUnsupportedExtension, "gltf-unsupported-extension"},
    CodeEntry{DiagnosticCode::GltfTooLarge, "gltf-too-large"},
    CodeEntry{DiagnosticCode::GltfMeshNotPrimitive, "gltf-mesh-not-primitive"},
    CodeEntry{DiagnosticCode::GltfMeshFit, "gltf-mesh-fit"},
    CodeEntry{DiagnosticCode::GltfLightApproximated, "gltf-light-approximated"},
    CodeEntry{DiagnosticCode::GltfExtraCamera, "gltf-extra-camera"},
    CodeEntry{DiagnosticCode::GltfNoCamera, "gltf-no-camera"},
    CodeEntry{DiagnosticCode::CameraFov, "camera-fov"},
    CodeEntry{DiagnosticCode::GltfIgnored, "gltf-ignored"},
    CodeEntry{DiagnosticCode::GltfExtrasStale, "gltf-extras-stale"},
    CodeEntry{DiagnosticCode::LossPov, "loss-pov"},
    CodeEntry{DiagnosticCode::PovSyntax, "pov-syntax"},
    CodeEntry{DiagnosticCode::PovUnsupported, "pov-unsupported"},
    CodeEntry{DiagnosticCode::PovRefused, "pov-refused"},
    CodeEntry{DiagnosticCode::PovLimit, "pov-limit"},
    CodeEntry{DiagnosticCode::PovUnknownIdentifier, "pov-unknown-identifier"},
    CodeEntry{DiagnosticCode::PovIgnored, "pov-ignored"},
    CodeEntry{DiagnosticCode::PovLoss, "pov-loss"},
    CodeEntry{DiagnosticCode::PovDegenerate, "pov-degenerate"},
    CodeEntry{DiagnosticCode::FileTooLarge, "file-too-large"},
    CodeEntry{DiagnosticCode::TooManyObjects, "too-many-objects"},
    CodeEntry{DiagnosticCode::ValueNotFinite, "value-not-finite"},
    CodeEntry{DiagnosticCode::GltfTooManyNodes, "gltf-too-many-nodes"},
    CodeEntry{DiagnosticCode::OutputFileFormat, "output-file-format"},
    CodeEntry{DiagnosticCode::OutputFileLinkLoop, "output-file-link-loop"},
};

}  // namespace

const std::vector<DiagnosticCode>& allDiagnosticCodes() {
  static const std::vector<DiagnosticCode> codes = [] {
    std::vector<DiagnosticCode> out;
    for (const CodeEntry& entry : kCodes) out.push_back(entry.code);
    return out;
  }();
  return codes;
}

std::string_view codeName(DiagnosticCode code) {
  for (const CodeEntry& entry : kCodes) {
    if (entry.code == code) return entry.name;
  }
  return "unknown";
}

Diagnostic& DiagnosticList::report(Severity severity, DiagnosticCode code, SourceSpan span,
                                   std::string message) {
  // Past the limit, warnings and notes are still counted but no longer kept.
  if (full() || (severity != Severity::Error && items_.size() >= 2 * errorLimit_)) {
    if (severity == Severity::Warning && !full()) ++warningCount_;
    discarded_ = Diagnostic{};
    return discarded_;
  }
  items_.push_back(Diagnostic{severity, code, file_, span, std::move(message), {}, {}, {}});
  std::size_t index = items_.size() - 1;
  if (severity == Severity::Error) ++errorCount_;
  if (severity == Severity::Warning) ++warningCount_;
  if (full()) {
    items_.push_back(Diagnostic{Severity::Note,
                                DiagnosticCode::TooManyErrors,
                                file_,
                                span,
                                "too many errors; stopped after " + std::to_string(errorLimit_),
                                {},
                                {},
                                {}});
  }
  // The caller may still attach a hint, notes or a fix-it to what it reported.
  return items_[index];
}

void DiagnosticList::append(const DiagnosticList& other) {
  for (const Diagnostic& d : other.items_) {
    items_.push_back(d);
    if (d.severity == Severity::Error) ++errorCount_;
    if (d.severity == Severity::Warning) ++warningCount_;
  }
}

}  // namespace scene

