// The modifiers of POV-Ray's objects that the scene model holds: the
// transformations (translate, rotate, scale, matrix, transform) and the
// texture (pigment, finish, texture, interior, material), read into a
// PovTransform and a PovMaterialPatch. Objects, #declare and #default take
// them alike; what the model cannot hold is reported as a loss.
#pragma once

#include <string_view>
#include <vector>

#include "libscene/formats/pov/pov_evaluator.h"
#include "libscene/formats/pov/pov_pattern_mean.h"

namespace scene {

class PovModifierReader : public PovEvaluator {
 protected:
  PovModifierReader(std::string_view text, const ReadOptions& options, DiagnosticList& out)
      : PovEvaluator(text, options, out) {}

  // One of translate, rotate, scale, matrix, transform (the word next),
  // applied to `t`.
  void transformItem(PovTransform& t);
  PovTransform transformBlock() final;
  void materialBlock(const PovToken& keyword, PovMaterialPatch& patch) final;
  void defaultsBlock() final;

  // #default's texture: what every object's own is laid over.
  const PovMaterialPatch& defaults() const { return defaults_; }

 private:
  void applyTransformItem(const PovToken& word, PovTransform& t);
  PovTransform declaredTransform(const PovToken& name);
  void pigmentItem(PovMaterialPatch& patch);
  void patternPigment(PovMaterialPatch& patch);
  std::vector<PovValue> listColours(std::string_view pattern);
  std::vector<PovMapEntry> colourMap(const PovToken& keyword);
  void finishItem(PovMaterialPatch& patch);
  void reflection(const PovToken& t, PovMaterialPatch& patch);
  void interiorItem(PovMaterialPatch& patch);
  void textureItem(PovMaterialPatch& patch);
  void materialItem(PovMaterialPatch& patch);
  double greyOf(const PovValue& v, const PovToken& keyword, std::string_view what);

  PovMaterialPatch defaults_ = povDefaultMaterial();
};

}  // namespace scene
