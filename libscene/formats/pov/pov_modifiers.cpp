#include "libscene/formats/pov/pov_modifiers.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/formats/pov/pov_pattern_mean.h"
#include "libscene/formats/pov/pov_value.h"
#include "libscene/text/number.h"
#include "libscene/text/reader_support.h"
#include "scenefile/transform.h"

namespace scene {

namespace {}  // namespace

// --- Transformations -----------------------------------------------------------

void PovModifierReader::transformItem(PovTransform& t) {
  PovToken word = take();
  applyTransformItem(word, t);
  requireFinite(t.m, word.span, "this " + std::string(word.text));
}

void PovModifierReader::applyTransformItem(const PovToken& word, PovTransform& t) {
  std::string_view w = word.text;
  if (w == "translate") {
    t.then(povTranslation(vectorValue("translate")));
  } else if (w == "rotate") {
    glm::dvec3 angles = vectorValue("rotate");
    // POV-Ray turns about x, then y, then z, by degrees; its matrices are
    // those of FORMATS.md's ROTATE_X/Y/Z (the numbers are the same; only
    // POV-Ray's left-handed picture of them differs).
    const TransformKind kinds[3] = {TransformKind::RotateX, TransformKind::RotateY,
                                    TransformKind::RotateZ};
    for (int i = 0; i < 3; ++i) {
      if (angles[i] == 0.0) continue;
      TransformOp op;
      op.kind = kinds[i];
      op.value = glm::dvec3(angles[i] * kPovDegree, 0.0, 0.0);
      t.then(transformMatrix(op));
    }
  } else if (w == "scale") {
    glm::dvec3 s = vectorValue("scale");
    for (int i = 0; i < 3; ++i) {
      if (s[i] == 0.0) {
        ignored(word.span,
                std::string("scale by 0 on ") + "xyz"[i] + " is read as 1, as POV-Ray does");
        s[i] = 1.0;
      }
    }
    t.then(povScaling(s));
  } else if (w == "matrix") {
    expectSymbol('<', "after matrix");
    double v[12];
    for (int i = 0; i < 12; ++i) {
      if (i) expectSymbol(',', "between the matrix's 12 numbers");
      v[i] = floatValue("a matrix entry");
    }
    expectSymbol('>', "after the matrix's 12 numbers");
    // POV-Ray's matrix is for row vectors (p' = p * M): its rows are our
    // columns.
    glm::dmat4 m(1.0);
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 3; ++r) m[c][r] = v[3 * c + r];
    }
    t.then(m);
  } else {  // transform
    if (peek().kind == PovTokenKind::Word && !peek().isSymbol('{')) {
      t.then(declaredTransform(take()));
    } else {
      t.then(transformBlock());
    }
  }
}

PovTransform PovModifierReader::declaredTransform(const PovToken& name) {
  const PovSymbol* symbol = findSymbol(name.text);
  if (!symbol) unknownIdentifier(name);
  if (symbol->failed) throw PovParseError{};
  if (symbol->kind != PovSymbolKind::Transform) {
    fail(name.span, "'" + std::string(name.text) + "' is " +
                        std::string(povSymbolKindName(symbol->kind)) + ", not a transform");
  }
  return symbol->transform;
}

PovTransform PovModifierReader::transformBlock() {
  PovToken open = expectSymbol('{', "after transform");
  PovTransform t;
  bool inverse = false;
  while (!acceptSymbol('}')) {
    const PovToken& p = peek();
    if (p.kind == PovTokenKind::Word && isPovTransformWord(p.text)) {
      transformItem(t);
    } else if (p.isWord("inverse")) {
      take();
      inverse = true;
    } else if (p.kind == PovTokenKind::Word && isDeclared(p.text)) {
      PovToken name = take();
      t.then(declaredTransform(name));
      requireFinite(t.m, name.span, "the transform '" + std::string(name.text) + "'");
    } else {
      fail(p.span,
           "a transform holds translate, rotate, scale, matrix or inverse, found " + describe(p));
    }
  }
  if (inverse && !t.identity) {
    t.m = glm::inverse(t.m);
    requireFinite(t.m, open.span, "the inverse of this transform");
  }
  return t;
}

// --- Materials -----------------------------------------------------------------

// #default { ... }: what it sets is laid under every object's texture when
// the scene is built.
void PovModifierReader::defaultsBlock() {
  expectSymbol('{', "after #default");
  while (!acceptSymbol('}')) {
    const PovToken& t = peek();
    if (t.isWord("pigment") || t.isWord("finish") || t.isWord("texture") || t.isWord("interior")) {
      PovToken keyword = take();
      materialBlock(keyword, defaults_);
    } else if (t.isWord("normal")) {
      PovToken keyword = take();
      unsupported(keyword.span, "a normal pattern");
      skipBlockAfter();
    } else {
      fail(t.span, "#default holds pigment, finish, texture or normal, found " + describe(t));
    }
  }
}

void PovModifierReader::materialBlock(const PovToken& keyword, PovMaterialPatch& patch) {
  std::string_view w = keyword.text;
  expectSymbol('{', "after " + std::string(w));
  // A declared one of the same kind may come first.
  if (peek().kind == PovTokenKind::Word) {
    const PovSymbol* declared = findSymbol(peek().text);
    if (declared && declared->kind != PovSymbolKind::Value) {
      PovToken name = take();
      PovSymbolKind want = w == "pigment"    ? PovSymbolKind::Pigment
                           : w == "finish"   ? PovSymbolKind::Finish
                           : w == "texture"  ? PovSymbolKind::Texture
                           : w == "interior" ? PovSymbolKind::Interior
                                             : PovSymbolKind::Material;
      if (declared->kind != want) {
        fail(name.span, "'" + std::string(name.text) + "' is " +
                            std::string(povSymbolKindName(declared->kind)) + ", not " +
                            std::string(povSymbolKindName(want)));
      }
      patch.merge(declared->patch);
    } else if (!declared && fromOtherInclude(peek().text)) {
      // T_Stone1 of stones.inc, Glass of glass.inc: names this reader does
      // not know. The object keeps the rest of its texture.
      PovToken name = take();
      unsupported(name.span,
                  "the " + std::string(w) + " '" + std::string(name.text) +
                      "' (declared in no file this reader reads)",
                  "it may come from " + firstOtherInclude() +
                      ", whose declarations this reader does not read; {0} "
                      "keeps the object without it");
      skipToBlockEnd();
    }
  }
  while (!acceptSymbol('}')) {
    const PovToken& t = peek();
    if (t.kind == PovTokenKind::End) fail(keyword.span, std::string(w) + " is not closed");
    if (t.kind == PovTokenKind::Directive) {
      directive();
      continue;
    }
    if (w == "pigment") {
      pigmentItem(patch);
    } else if (w == "finish") {
      finishItem(patch);
    } else if (w == "interior") {
      interiorItem(patch);
    } else if (w == "texture") {
      textureItem(patch);
    } else {
      materialItem(patch);
    }
  }
}

void PovModifierReader::pigmentItem(PovMaterialPatch& patch) {
  const PovToken& t = peek();
  if (t.kind == PovTokenKind::Word) {
    if (isPovTransformWord(t.text)) {
      PovTransform ignoredTransform;  // a plain colour looks the same moved
      transformItem(ignoredTransform);
      return;
    }
    if (t.isWord("quick_color") || t.isWord("quick_colour")) {
      take();
      colour();
      return;
    }
    if (t.isWord("image_map") || t.isWord("bump_map") || t.isWord("material_map")) {
      PovToken word = take();
      refuse(word.span, "'" + std::string(word.text) + "' reads an image file: refused",
             "this reader reads no file but the scene itself");
    }
    if (isPovPattern(t.text)) {
      patternPigment(patch);
      return;
    }
  }
  PovValue c = colour();
  patch.colour = glm::dvec3(c.v[0], c.v[1], c.v[2]);
  patch.filter = c.v[3];
  patch.transmit = c.v[4];
  patch.pattern.reset();
}

// --- Patterns ------------------------------------------------------------------

// A pattern and its modifiers, to the pigment's closing brace. The model
// holds one colour an object: checker, hexagon, brick and the patterns of a
// colour_map become their mean colour (a loss the scene reports for each
// object it colours); a pattern of pigments, of an image or of a function,
// or one without its colour_map, stays unsupported.
void PovModifierReader::patternPigment(PovMaterialPatch& patch) {
  std::optional<PovToken> pattern;
  std::vector<PovValue> listed;
  std::optional<std::vector<PovMapEntry>> map;
  glm::dvec3 brickSize(8.0, 3.0, 4.5);  // POV-Ray's defaults
  double mortar = 0.5;
  while (!peek().isSymbol('}') && peek().kind != PovTokenKind::End) {
    const PovToken& t = peek();
    if (t.kind == PovTokenKind::Directive) {
      directive();
      continue;
    }
    if (t.kind == PovTokenKind::Word && isPovTransformWord(t.text)) {
      PovTransform ignoredTransform;  // a moved pattern has the same mean
      transformItem(ignoredTransform);
      continue;
    }
    PovToken word = take();
    std::string_view w = word.text;
    if (word.kind != PovTokenKind::Word) {
      fail(word.span, "expected a pattern modifier, found " + describe(word));
    } else if (!pattern && isPovListPattern(w)) {
      pattern = word;
      listed = listColours(w);
    } else if (!pattern && isPovMapPattern(w)) {
      pattern = word;
      if (w == "gradient") vectorValue("gradient's direction");
      if (w == "spiral1" || w == "spiral2") floatValue(std::string(w) + "'s number of arms");
    } else if (w == "color_map" || w == "colour_map") {
      map = colourMap(word);
    } else if (w == "turbulence" || w == "brick_size") {
      glm::dvec3 v = vectorValue(w);
      if (w == "brick_size") brickSize = v;
    } else if (w == "octaves" || w == "omega" || w == "lambda" || w == "frequency" ||
               w == "phase" || w == "mortar") {
      double v = floatValue(w);
      if (w == "mortar") mortar = v;
    } else {
      std::string what = pattern && (w == "pigment" || w == "texture")
                             ? "'" + std::string(pattern->text) + "' of " + std::string(w) + "s"
                             : "'" + std::string(w) + "'";
      unsupported(word.span, "the pigment pattern " + what);
      skipToBlockEnd();
      return;
    }
  }
  if (!pattern || (isPovMapPattern(pattern->text) && !map)) {
    const PovToken& at = pattern ? *pattern : peek();
    unsupported(at.span, pattern ? "the pigment pattern '" + std::string(pattern->text) +
                                       "' without a colour_map"
                                 : std::string("a colour_map without a pattern"));
    return;
  }
  std::string_view name = pattern->text;
  PovValue mean = map               ? povColourMapMean(*map)
                  : name == "brick" ? povBrickMean(listed[0], listed[1], brickSize, mortar)
                                    : povEqualShareMean(listed);
  patch.colour = glm::dvec3(mean.v[0], mean.v[1], mean.v[2]);
  patch.filter = mean.v[3];
  patch.transmit = mean.v[4];
  patch.pattern = PovPatternMean{std::string(name), pattern->span};
}

// The colours after checker, hexagon or brick, commas between them optional
// as in POV-Ray; POV-Ray's own for those not given.
std::vector<PovValue> PovModifierReader::listColours(std::string_view pattern) {
  std::vector<PovValue> colours = povDefaultListColours(pattern);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    if (i > 0) acceptSymbol(',');
    const PovToken& t = peek();
    bool modifier = t.isSymbol('}') || t.kind == PovTokenKind::End ||
                    (t.kind == PovTokenKind::Word &&
                     (isPovPattern(t.text) || isPovTransformWord(t.text) || t.isWord("pigment") ||
                      t.isWord("texture") || t.isWord("brick_size") || t.isWord("mortar")));
    if (modifier) break;
    colours[i] = colour();
  }
  return colours;
}

// colour_map { [value colour] ... }, or POV-Ray 3.1's [v1, v2 colour1
// colour2]; entries in ascending order of value, at most POV-Ray's 256.
std::vector<PovMapEntry> PovModifierReader::colourMap(const PovToken& keyword) {
  expectSymbol('{', "after " + std::string(keyword.text));
  std::vector<PovMapEntry> entries;
  while (!acceptSymbol('}')) {
    PovToken open = expectSymbol('[', "before a colour_map entry");
    double value = floatValue("a colour_map entry's value");
    acceptSymbol(',');
    if (peek().kind == PovTokenKind::Number) {
      double second = floatValue("a colour_map entry's second value");
      PovValue first = colour();
      entries.push_back({value, first});
      entries.push_back({second, colour()});
    } else {
      entries.push_back({value, colour()});
    }
    expectSymbol(']', "after a colour_map entry");
    if (entries.size() > kPovMaxMapEntries) {
      fail(open.span, "a colour_map holds at most " + std::to_string(kPovMaxMapEntries) +
                          " entries, as in POV-Ray");
    }
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const PovMapEntry& a, const PovMapEntry& b) { return a.value < b.value; });
  return entries;
}

void PovModifierReader::finishItem(PovMaterialPatch& patch) {
  PovToken t = take();
  std::string_view w = t.text;
  if (t.kind != PovTokenKind::Word) fail(t.span, "expected a finish keyword, found " + describe(t));
  if (w == "ambient" || w == "emission") {
    PovValue v = colour();
    if (w == "emission") {
      if (v.v[0] != 0.0 || v.v[1] != 0.0 || v.v[2] != 0.0) {
        loss(t.span, "emission is dropped: the renderer's surfaces do not glow");
      }
      return;
    }
    patch.ambient = greyOf(v, t, "ambient");
  } else if (w == "diffuse") {
    if (acceptWord("albedo")) loss(t.span, "diffuse albedo is read as a plain diffuse");
    patch.diffuse = floatValue("diffuse");
    if (acceptSymbol(',')) {
      double back = floatValue("diffuse's backside");
      if (back != 0.0) loss(t.span, "diffuse backside light is dropped");
    }
  } else if (w == "phong" || w == "specular") {
    if (acceptWord("albedo"))
      loss(t.span, std::string(w) + " albedo is read as a plain " + std::string(w));
    double v = floatValue(w);
    (w == "phong" ? patch.phong : patch.specular) = v;
  } else if (w == "phong_size") {
    patch.phongSize = floatValue(w);
  } else if (w == "roughness") {
    patch.roughness = floatValue(w);
  } else if (w == "reflection") {
    reflection(t, patch);
  } else if (w == "brilliance" || w == "crand" || w == "metallic" || w == "reflection_exponent") {
    std::optional<double> v = w == "metallic" ? optionalFloat() : floatValue(w);
    double neutral = w == "brilliance" ? 1.0 : 0.0;
    if (w == "metallic" && !v) v = 1.0;
    if (*v != neutral) loss(t.span, std::string(w) + " " + formatNumber(*v) + " is dropped");
  } else if (w == "conserve_energy") {
    optionalFloat();
    loss(t.span, "conserve_energy is dropped");
  } else if (w == "irid" || w == "subsurface") {
    loss(t.span, std::string(w) + " is dropped");
    skipBlockAfter();
  } else if (w == "fresnel") {
    optionalFloat();
    loss(t.span,
         "fresnel is dropped: the renderer weighs reflection by Fresnel only for "
         "transparent objects");
  } else {
    Diagnostic& d = out_.error(DiagnosticCode::PovSyntax, t.span,
                               "'" + std::string(w.substr(0, 40)) + "' is no finish keyword");
    static constexpr std::string_view kFinish[] = {
        "ambient",   "diffuse",    "phong",      "phong_size", "specular",
        "roughness", "reflection", "brilliance", "metallic",   "emission"};
    if (auto guess = suggestKeyword(w, kFinish))
      d.hint = "did you mean '" + std::string(*guess) + "'?";
    throw PovParseError{};
  }
}

void PovModifierReader::reflection(const PovToken& t, PovMaterialPatch& patch) {
  if (!peek().isSymbol('{')) {
    patch.reflection = greyOf(colour(), t, "reflection");
    return;
  }
  take();
  double value = greyOf(colour(), t, "reflection");
  if (acceptSymbol(',')) {
    double h = greyOf(colour(), t, "reflection");
    if (h != value) {
      loss(t.span, "a reflection that varies with the angle (" + formatNumber(value) + " to " +
                       formatNumber(h) + ") becomes " + formatNumber(value));
    }
  }
  while (!acceptSymbol('}')) {
    PovToken w = take();
    if (w.kind != PovTokenKind::Word)
      fail(w.span, "expected a reflection keyword, found " + describe(w));
    if (w.text == "fresnel" || w.text == "metallic") {
      std::optional<double> v = optionalFloat();
      if (v.value_or(1.0) != 0.0) loss(w.span, std::string(w.text) + " reflection is dropped");
    } else if (w.text == "falloff" || w.text == "exponent") {
      double v = floatValue(w.text);
      if (v != 1.0) loss(w.span, std::string(w.text) + " " + formatNumber(v) + " is dropped");
    } else {
      fail(w.span, "'" + std::string(w.text) + "' is no reflection keyword");
    }
  }
  patch.reflection = value;
}

void PovModifierReader::interiorItem(PovMaterialPatch& patch) {
  PovToken t = take();
  std::string_view w = t.text;
  if (t.kind != PovTokenKind::Word)
    fail(t.span, "expected an interior keyword, found " + describe(t));
  if (w == "ior") {
    patch.ior = floatValue("ior");
  } else if (w == "media") {
    unsupported(t.span, "media");
    skipBlockAfter();
  } else if (w == "caustics" || w == "dispersion" || w == "dispersion_samples" ||
             w == "fade_distance" || w == "fade_power") {
    double v = floatValue(w);
    bool neutral = (w == "dispersion" && v == 1.0) || (w != "dispersion" && v == 0.0);
    if (!neutral) loss(t.span, std::string(w) + " " + formatNumber(v) + " is dropped");
  } else if (w == "fade_color" || w == "fade_colour") {
    colour();
    loss(t.span, std::string(w) + " is dropped");
  } else {
    fail(t.span, "'" + std::string(w.substr(0, 40)) + "' is no interior keyword");
  }
}

void PovModifierReader::textureItem(PovMaterialPatch& patch) {
  const PovToken& t = peek();
  if (t.isWord("pigment") || t.isWord("finish")) {
    PovToken keyword = take();
    materialBlock(keyword, patch);
  } else if (t.isWord("normal")) {
    PovToken keyword = take();
    unsupported(keyword.span, "a normal pattern");
    skipBlockAfter();
  } else if (t.kind == PovTokenKind::Word && isPovTransformWord(t.text)) {
    PovTransform ignoredTransform;
    transformItem(ignoredTransform);
  } else if (t.kind == PovTokenKind::Word && isPovPattern(t.text)) {
    PovToken keyword = take();
    unsupported(keyword.span, "the texture pattern '" + std::string(keyword.text) + "'");
    skipToBlockEnd();
  } else {
    fail(t.span, "a texture holds pigment, finish and normal, found " + describe(t));
  }
}

void PovModifierReader::materialItem(PovMaterialPatch& patch) {
  const PovToken& t = peek();
  if (t.isWord("texture") || t.isWord("interior")) {
    PovToken keyword = take();
    materialBlock(keyword, patch);
  } else if (t.kind == PovTokenKind::Word && isPovTransformWord(t.text)) {
    PovTransform ignoredTransform;
    transformItem(ignoredTransform);
  } else {
    fail(t.span, "a material holds texture and interior, found " + describe(t));
  }
}

// One number for a colour that the model holds as one (ambient,
// reflection): the colour's grey, or its mean with a loss reported.
double PovModifierReader::greyOf(const PovValue& v, const PovToken& keyword,
                                 std::string_view what) {
  if (v.v[0] == v.v[1] && v.v[1] == v.v[2]) return v.v[0];
  double mean = (v.v[0] + v.v[1] + v.v[2]) / 3.0;
  // Three large channels overflow their sum, not their mean.
  if (!std::isfinite(mean)) mean = v.v[0] / 3.0 + v.v[1] / 3.0 + v.v[2] / 3.0;
  loss(keyword.span, "a coloured " + std::string(what) + " becomes its mean " + formatNumber(mean),
       std::string(what) + " is one number in the scene model");
  return mean;
}

}  // namespace scene
