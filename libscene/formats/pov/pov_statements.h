// The statements of a POV-Ray scene, read into the parts the scene is
// built from: camera, light_source, background, the four shapes and
// object { Name }, with the directives between them. After an error the
// statement is abandoned and reading resumes at the next one.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "libscene/formats/pov/pov_modifiers.h"
#include "libscene/formats/pov/pov_scene_parts.h"

namespace scene {

class PovStatementReader final : public PovModifierReader {
 public:
  PovStatementReader(std::string_view text, const ReadOptions& options, DiagnosticList& out)
      : PovModifierReader(text, options, out) {}

  // Reads every statement; false when reading stopped early (a limit, or
  // the error list is full), and the scene is not to be built.
  bool run();

  const PovSceneParts& parts() const { return parts_; }
  using PovModifierReader::defaults;
  using PovTokenStream::lexer;

 private:
  void statement();
  std::optional<PovToken> nextKeyword(std::string_view block, PovTransform& transform);

  void camera();
  void cameraItem(const PovToken& word, PovCameraState& c, std::optional<glm::dvec3>& lookAt,
                  std::optional<double>& angle);
  void lookAtPoint(const PovToken& keyword, const glm::dvec3& lookAt, PovCameraState& c);
  void light();
  void background();

  PovPendingObject objectStatement() final;
  void sphereShape(const PovToken& keyword, PovPendingObject& object);
  void boxShape(const PovToken& keyword, PovPendingObject& object);
  void cylinderShape(const PovToken& keyword, PovPendingObject& object);
  void planeShape(const PovToken& keyword, PovPendingObject& object);
  void declaredObject(PovPendingObject& object);
  void objectModifiers(PovPendingObject& object, const PovToken& keyword);
  void countElement(SourceSpan span);
  [[noreturn]] void degenerate(SourceSpan span, std::string message);

  PovSceneParts parts_;
};

}  // namespace scene
