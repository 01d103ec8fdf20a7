#include "libscene/formats/instruction/instruction_reader.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

enum class Block { Camera, Light, Object, Material, Transformation };

constexpr std::array<std::string_view, 5> kBlockNames = {"CAMERA", "LIGHT", "OBJECT", "MATERIAL",
                                                         "TRANSFORMATION"};

std::string_view blockName(Block block) { return kBlockNames[static_cast<std::size_t>(block)]; }

std::optional<Block> blockFromName(std::string_view name) {
  for (std::size_t i = 0; i < kBlockNames.size(); ++i) {
    if (kBlockNames[i] == name) return static_cast<Block>(i);
  }
  return std::nullopt;
}

// Every keyword a line may start with, for did-you-mean.
constexpr std::array<std::string_view, 18> kLineKeywords = {
    "OUTPUT_FILE", "START",    "END",       "LOCATION",     "LOOK_AT",      "COLOUR",
    "AMBIENT",     "DIFFUSE",  "SPECULAR",  "SHININESS",    "REFLECTIVITY", "TRANSPARENCY",
    "RI",          "SCALE",    "TRANSLATE", "ROTATE_X",     "ROTATE_Y",     "ROTATE_Z"};

constexpr std::string_view kObjectKindNames[] = {
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) #record,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};

// The property keywords, the block each belongs to and how many numbers
// it takes.
struct PropertyRule {
  std::string_view keyword;
  Block block;
  int count;
};
constexpr std::array<PropertyRule, 17> kProperties = {{
    {"LOCATION", Block::Camera, 3},
    {"LOOK_AT", Block::Camera, 3},
    {"LOCATION", Block::Light, 3},
    {"COLOUR", Block::Light, 3},
    {"COLOUR", Block::Material, 3},
    {"AMBIENT", Block::Material, 1},
    {"DIFFUSE", Block::Material, 1},
    {"SPECULAR", Block::Material, 1},
    {"SHININESS", Block::Material, 1},
    {"REFLECTIVITY", Block::Material, 1},
    {"TRANSPARENCY", Block::Material, 1},
    {"RI", Block::Material, 1},
    {"SCALE", Block::Transformation, 3},
    {"TRANSLATE", Block::Transformation, 3},
    {"ROTATE_X", Block::Transformation, 1},
    {"ROTATE_Y", Block::Transformation, 1},
    {"ROTATE_Z", Block::Transformation, 1},
}};

const PropertyRule* findProperty(std::string_view keyword, Block block) {
  for (const PropertyRule& rule : kProperties) {
    if (rule.keyword == keyword && rule.block == block) return &rule;
  }
  return nullptr;
}

bool isPropertyKeyword(std::string_view keyword) {
  for (const PropertyRule& rule : kProperties) {
    if (rule.keyword == keyword) return true;
  }
  return false;
}

std::vector<std::string_view> keywordsOf(Block block) {
  std::vector<std::string_view> out;
  for (const PropertyRule& rule : kProperties) {
    if (rule.block == block) out.push_back(rule.keyword);
  }
  out.push_back("END");
  if (block == Block::Object) out.push_back("START");
  return out;
}

std::string article(Block block) { return block == Block::Object ? "an " : "a "; }

// An open block with what has been read inside it so far.
struct OpenBlock {
  Block block;
  SourceSpan start;  // the START line
  // Properties seen, by keyword, for duplicates and missing ones.
  std::vector<std::pair<std::string_view, SourceSpan>> seen;
  std::array<glm::dvec3, 2> vectors{};  // CAMERA: location, look_at; LIGHT: location, colour
  bool valuesOk = true;
  bool duplicate = false;  // a second CAMERA: checked, then dropped

  const SourceSpan* find(std::string_view keyword) const {
    for (const auto& [k, span] : seen) {
      if (k == keyword) return &span;
    }
    return nullptr;
  }
};

class InstructionParser {
 public:
  InstructionParser(std::string_view text, const ReadOptions& options, ReadResult& result)
      : cursor_(text), options_(options), scene_(result.scene), out_(result.diagnostics) {}

  void run() {
    while (!out_.full() && !stopped_ && cursor_.next()) {
      if (++linesSinceStopCheck_ == kLinesPerStopCheck) {
        linesSinceStopCheck_ = 0;
        if (options_.stop.stop_requested()) {
          stopped_ = true;
          break;
        }
      }
      if (cursor_.blank() || reportComment(cursor_, out_)) continue;
      if (reportInvalidByte(cursor_, out_)) {
        // A damaged START or END is still read, as far as the damage, so
        // that the blocks stay balanced; any other damaged line is skipped.
        cursor_.cutAtInvalidByte();
        if (!stack_.empty()) stack_.back().valuesOk = false;
        sawContent_ = true;
        std::string_view first = cursor_.blank() ? "" : cursor_.token(0).text;
        if (first != "START" && first != "END") continue;
      }
      std::string_view keyword = lineKeyword();
      if (skipping_ && !endsSkippedBlock(keyword)) continue;
      if (!sawContent_) {
        sawContent_ = true;
        if (keyword == "OUTPUT_FILE") {
          readOutputFile();
          continue;
        }
        out_.error(DiagnosticCode::MissingOutputFile, cursor_.tokenSpan(0),
                   "an instruction file starts with OUTPUT_FILE")
            .hint = "add a first line such as 'OUTPUT_FILE picture.ppm'";
      }
      if (keyword == "START") {
        readStart();
      } else if (keyword == "END") {
        readEnd();
      } else if (keyword == "OUTPUT_FILE") {
        Diagnostic& d = out_.error(DiagnosticCode::UnexpectedLine, cursor_.tokenSpan(0),
                                   "OUTPUT_FILE may appear only once, on the first line");
        if (scene_.outputFile) d.notes.push_back({scene_.outputFileSpan, "the first is here"});
      } else {
        readProperty(keyword);
      }
    }
    finish();
  }

 private:
  void readOutputFile() {
    if (cursor_.tokenCount() != 2) {
      SourceSpan where = cursor_.tokenCount() < 2 ? cursor_.endOfLine() : cursor_.tokenSpan(2);
      out_.error(DiagnosticCode::OutputFileName, where,
                 cursor_.tokenCount() < 2 ? "OUTPUT_FILE needs a file name"
                                          : "OUTPUT_FILE takes one file name without spaces");
      return;
    }
    scene_.outputFile = std::string(cursor_.token(1).text);
    scene_.outputFileSpan = cursor_.tokenSpan(1);
  }

  // The line's first token, or the keyword it spells in another case (which
  // is reported, and then read as that keyword so that blocks stay balanced).
  std::string_view lineKeyword() {
    std::string_view word = cursor_.token(0).text;
    if (std::find(kLineKeywords.begin(), kLineKeywords.end(), word) != kLineKeywords.end()) {
      return word;
    }
    if (auto keyword = keywordInOtherCase(word, kLineKeywords)) {
      reportUnknownKeyword(cursor_, 0, kLineKeywords, expectedHere(), out_);
      return *keyword;
    }
    return word;
  }

  // What may start a line where the cursor is, in words.
  std::string expectedHere() const {
    if (stack_.empty()) return "START or END";
    Block block = stack_.back().block;
    if (block == Block::Object) return "START MATERIAL, START TRANSFORMATION or END";
    return "a property of " + article(block) + std::string(blockName(block)) + " block";
  }

  // The block a START or END names (token 1), spelt right or in another case.
  std::optional<Block> namedBlock() {
    std::string_view word = cursor_.token(1).text;
    if (auto block = blockFromName(word)) return block;
    if (auto name = keywordInOtherCase(word, kBlockNames)) {
      reportUnknownKeyword(cursor_, 1, kBlockNames, "a block name", out_);
      return blockFromName(*name);
    }
    return std::nullopt;
  }

  // While an unknown block is skipped: true for a line that ends the skip
  // and is then read as usual (an END of an open block, a START of a
  // top-level block); its own END ends the skip and is consumed.
  bool endsSkippedBlock(std::string_view keyword) {
    if (cursor_.tokenCount() < 2 || (keyword != "END" && keyword != "START")) return false;
    std::string_view name = cursor_.token(1).text;
    if (keyword == "END" && name == *skipping_) {
      skipping_.reset();
      return false;
    }
    std::optional<Block> block = blockFromName(name);
    if (!block) return false;
    bool endsOpenBlock = keyword == "END" && std::any_of(stack_.begin(), stack_.end(),
                                                         [&](const OpenBlock& open) {
                                                           return open.block == *block;
                                                         });
    bool startsTopLevel = keyword == "START" && (*block == Block::Camera ||
                                                 *block == Block::Light ||
                                                 *block == Block::Object);
    if (endsOpenBlock || startsTopLevel) skipping_.reset();
    return !skipping_;
  }

  void readStart() {
    if (cursor_.tokenCount() < 2) {
      out_.error(DiagnosticCode::TokenCount, cursor_.endOfLine(), "START needs a block name");
      return;
    }
    std::optional<Block> block = namedBlock();
    if (!block) {
      reportUnknownKeyword(cursor_, 1, kBlockNames, "a block name", out_);
      // Its lines would only repeat the error: skip to its END.
      skipping_ = std::string(cursor_.token(1).text);
      return;
    }
    if ((*block == Block::Object || *block == Block::Light) &&
        ++objectsSeen_ > options_.maxObjects) {
      reportTooManyObjects(cursor_.tokenSpan(0), options_.maxObjects, out_);
      stopped_ = true;
      return;
    }
    std::string name(blockName(*block));
    bool section = *block == Block::Material || *block == Block::Transformation;
    // A START that cannot nest here most likely means the open block lacks
    // its END: close what is open until the START fits.
    while (!stack_.empty()) {
      Block open = stack_.back().block;
      bool fits = section && open == Block::Object;
      if (fits) break;
      reportUnclosed(stack_.back(), "before START " + std::string(name));
      closeTop(false);
    }
    if (section && stack_.empty()) {
      out_.error(DiagnosticCode::UnexpectedLine, cursor_.tokenSpan(0),
                 "START " + std::string(name) + " must stand inside an OBJECT block");
      // Read it anyway, so that its lines are checked.
    }
    std::size_t expectedTokens = *block == Block::Object ? 3 : 2;
    if (*block == Block::Object && cursor_.tokenCount() < 3) {
      out_.error(DiagnosticCode::TokenCount, cursor_.endOfLine(),
                 "START OBJECT needs the object's kind (" + objectKindChoices() + ")");
    } else if (cursor_.tokenCount() > expectedTokens) {
      out_.error(DiagnosticCode::TokenCount, cursor_.tokenSpan(expectedTokens),
                 "unexpected text after START " + std::string(name));
    }
    OpenBlock open{*block, cursor_.tokenSpan(0), {}, {}, true};
    open.start.length = cursor_.lineSpan().length;
    if (*block == Block::Object) {
      Object object;
      object.span = open.start;
      object.transforms.emplace();
      if (cursor_.tokenCount() >= 3) {
        std::string_view kindName = cursor_.token(2).text;
        if (auto kind = objectKindFromName(kindName)) {
          object.kind = *kind;
        } else {
          Diagnostic& d = out_.error(DiagnosticCode::UnknownObjectKind, cursor_.tokenSpan(2),
                                     "unknown object kind '" + std::string(kindName.substr(0, 40)) +
                                         "', expected " + objectKindChoices());
          if (auto guess = suggestKeyword(kindName, kObjectKindNames)) {
            d.fixIt = FixIt{cursor_.tokenSpan(2), std::string(*guess)};
            d.hint = "did you mean '" + std::string(*guess) + "'?";
            if (keywordInOtherCase(kindName, kObjectKindNames)) {
              // "sphere" is read as the SPHERE it means.
              d.hint = "keywords are upper case: " + d.hint;
              object.kind = *objectKindFromName(*guess);
            }
          }
          if (!keywordInOtherCase(kindName, kObjectKindNames)) open.valuesOk = false;
        }
      } else {
        open.valuesOk = false;
      }
      object_ = std::move(object);
      transformStart_.reset();
    }
    if (*block == Block::Camera) {
      if (cameraSpan_) {
        out_.error(DiagnosticCode::DuplicateCamera, open.start, "a scene has exactly one CAMERA")
            .notes.push_back({*cameraSpan_, "the first CAMERA is here"});
        open.duplicate = true;
      } else {
        cameraSpan_ = open.start;
      }
    }
    if (section && !stack_.empty()) {
      if (const SourceSpan* previous = stack_.back().find(name)) {
        out_.error(DiagnosticCode::DuplicateSection, cursor_.tokenSpan(1),
                   "an OBJECT holds at most one " + std::string(name) + " section")
            .notes.push_back({*previous, "the first is here"});
      } else {
        stack_.back().seen.emplace_back(blockName(*block), cursor_.tokenSpan(1));
      }
      if (*block == Block::Transformation) transformStart_ = open.start;
    }
    stack_.push_back(std::move(open));
  }

  void readEnd() {
    if (cursor_.tokenCount() < 2) {
      out_.error(DiagnosticCode::TokenCount, cursor_.endOfLine(), "END needs a block name");
      return;
    }
    if (cursor_.tokenCount() > 2) {
      out_.error(DiagnosticCode::TokenCount, cursor_.tokenSpan(2),
                 "unexpected text after END " + std::string(cursor_.token(1).text));
    }
    std::optional<Block> block = namedBlock();
    if (!block) {
      reportUnknownKeyword(cursor_, 1, kBlockNames, "a block name", out_);
      return;
    }
    std::string name(blockName(*block));
    // Which open block does this END close?
    std::size_t match = stack_.size();
    for (std::size_t i = stack_.size(); i-- > 0;) {
      if (stack_[i].block == *block) {
        match = i;
        break;
      }
    }
    if (match == stack_.size()) {
      if (stack_.empty()) {
        out_.error(DiagnosticCode::UnexpectedEnd, cursor_.lineSpan(),
                   "END " + std::string(name) + " without a START " + std::string(name));
      } else {
        out_.error(DiagnosticCode::MismatchedEnd, cursor_.lineSpan(),
                   "END " + std::string(name) + " does not close the open " +
                       std::string(blockName(stack_.back().block)) + " block")
            .notes.push_back({stack_.back().start, "the block opens here"});
      }
      return;
    }
    while (stack_.size() > match + 1) {
      reportUnclosed(stack_.back(), "before END " + std::string(name));
      closeTop(false);
    }
    closeTop(true);
  }

  void readProperty(std::string_view keyword) {
    if (stack_.empty()) {
      if (isPropertyKeyword(keyword)) {
        out_.error(DiagnosticCode::UnexpectedLine, cursor_.tokenSpan(0),
                   std::string(keyword) + " must stand inside a block")
            .hint = "only START lines may stand between blocks";
      } else {
        reportUnknownKeyword(cursor_, 0, kLineKeywords, "START or END", out_);
      }
      return;
    }
    OpenBlock& open = stack_.back();
    const PropertyRule* rule = findProperty(keyword, open.block);
    if (!rule) {
      if (isPropertyKeyword(keyword)) {
        out_.error(DiagnosticCode::UnexpectedLine, cursor_.tokenSpan(0),
                   std::string(keyword) + " does not belong in " + article(open.block) +
                       std::string(blockName(open.block)) + " block");
      } else {
        reportUnknownKeyword(cursor_, 0, keywordsOf(open.block), expectedHere(), out_);
      }
      open.valuesOk = false;
      return;
    }
    // A property counts as given even when its numbers are bad, so that it
    // is not also reported missing.
    SourceSpan keywordSpan = cursor_.tokenSpan(0);
    if (open.block != Block::Transformation) {
      if (const SourceSpan* previous = open.find(keyword)) {
        out_.error(DiagnosticCode::DuplicateProperty, keywordSpan,
                   std::string(keyword) + " is given twice in this " +
                       std::string(blockName(open.block)) + " block")
            .notes.push_back({*previous, "the first is here"});
        open.valuesOk = false;
        return;
      }
      open.seen.emplace_back(rule->keyword, keywordSpan);
    }
    double values[3] = {0.0, 0.0, 0.0};
    if (!readNumbers(cursor_, 1, static_cast<std::size_t>(rule->count), values, keyword, out_)) {
      open.valuesOk = false;
      return;
    }
    glm::dvec3 v(values[0], values[1], values[2]);
    switch (open.block) {
      case Block::Camera:
        open.vectors[keyword == "LOCATION" ? 0 : 1] = v;
        if (keyword == "LOOK_AT") lookAtSpan_ = cursor_.lineSpan();
        return;
      case Block::Light:
        if (keyword == "COLOUR") {
          RecordSpans spans = RecordSpans::uniform(keywordSpan);
          for (int i = 0; i < 3; ++i) spans.colour[i] = cursor_.tokenSpan(1 + i);
          std::size_t before = out_.errorCount();
          checkColour(v, RecordRole::Light, spans, out_);
          if (out_.errorCount() != before) open.valuesOk = false;
        }
        open.vectors[keyword == "LOCATION" ? 0 : 1] = v;
        return;
      case Block::Material:
        readMaterialValue(keyword, v, open);
        return;
      case Block::Transformation:
        readTransform(keyword, v, open);
        return;
      case Block::Object:
        return;
    }
  }

  void readMaterialValue(std::string_view keyword, const glm::dvec3& v, OpenBlock& open) {
    if (!object_) return;
    std::size_t before = out_.errorCount();
    if (keyword == "COLOUR") {
      RecordSpans spans = RecordSpans::uniform(cursor_.tokenSpan(0));
      for (int i = 0; i < 3; ++i) spans.colour[i] = cursor_.tokenSpan(1 + i);
      checkColour(v, RecordRole::Object, spans, out_);
      object_->material.colour = v;
    } else {
      for (MaterialProperty p : kMaterialProperties) {
        if (materialPropertyName(p) == keyword) {
          checkMaterialValue(p, v.x, cursor_.tokenSpan(1), out_);
          materialValue(object_->material, p) = v.x;
        }
      }
    }
    if (out_.errorCount() != before) open.valuesOk = false;
  }

  void readTransform(std::string_view keyword, const glm::dvec3& v, OpenBlock& open) {
    TransformOp op;
    op.span = cursor_.lineSpan();
    op.value = v;
    if (keyword == "SCALE") {
      op.kind = TransformKind::Scale;
      for (int i = 0; i < 3; ++i) {
        if (v[i] == 0.0) {
          out_.error(DiagnosticCode::ZeroScale, cursor_.tokenSpan(1 + i),
                     "a SCALE factor of 0 flattens the object")
              .hint = "negative factors mirror and are allowed; 0 is not";
          open.valuesOk = false;
        }
      }
    } else if (keyword == "TRANSLATE") {
      op.kind = TransformKind::Translate;
    } else {
      op.kind = keyword == "ROTATE_X"   ? TransformKind::RotateX
                : keyword == "ROTATE_Y" ? TransformKind::RotateY
                                        : TransformKind::RotateZ;
      op.value = glm::dvec3(v.x, 0.0, 0.0);
    }
    if (object_) object_->transforms->push_back(op);
  }

  void reportUnclosed(const OpenBlock& open, const std::string& where) {
    out_.error(DiagnosticCode::UnclosedBlock, cursor_.lineSpan(),
               "the " + std::string(blockName(open.block)) + " block opened at line " +
                   std::to_string(open.start.line) + " is not closed " + where)
        .notes.push_back({open.start, "the block opens here"});
  }

  // Ends the innermost block; `complete` is false when it had no END, and
  // then only its structure, not its content, is judged.
  void closeTop(bool complete) {
    OpenBlock open = std::move(stack_.back());
    stack_.pop_back();
    switch (open.block) {
      case Block::Camera:
        if (complete) finishCamera(open);
        return;
      case Block::Light:
        if (complete) finishLight(open);
        return;
      case Block::Object:
        if (complete && open.valuesOk && object_) finishObject();
        object_.reset();
        return;
      case Block::Material:
      case Block::Transformation:
        if (!(open.valuesOk && complete) && !stack_.empty()) stack_.back().valuesOk = false;
        return;
    }
  }

  bool requireProperties(const OpenBlock& open, std::initializer_list<std::string_view> keys) {
    bool ok = true;
    for (std::string_view key : keys) {
      if (!open.find(key)) {
        out_.error(DiagnosticCode::MissingProperty, open.start,
                   std::string(blockName(open.block)) + " block has no " + std::string(key));
        ok = false;
      }
    }
    return ok;
  }

  void finishCamera(const OpenBlock& open) {
    bool ok = requireProperties(open, {"LOCATION", "LOOK_AT"}) && open.valuesOk;
    if (ok && open.vectors[0] == open.vectors[1]) {
      out_.error(DiagnosticCode::CameraLookAtLocation, lookAtSpan_,
                 "LOOK_AT is the camera's own LOCATION, so it looks nowhere");
      ok = false;
    } else if (ok) {
      // Any finite non-zero difference has a direction (cameraFromLookAt
      // scales it by a power of two first, so 1e-320 or 1e200 apart is
      // fine); only a difference that overflows has none.
      glm::dvec3 d = open.vectors[1] - open.vectors[0];
      if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
        out_.error(DiagnosticCode::CameraDegenerate, lookAtSpan_,
                   "LOOK_AT is too far from LOCATION: their difference overflows a double")
            .hint = "scale the scene so that its coordinates stay below about 1e307";
        ok = false;
      }
    }
    if (!ok || open.duplicate) return;
    scene_.camera.matrix = cameraFromLookAt(open.vectors[0], open.vectors[1]);
    scene_.camera.lookAt = open.vectors[1];
    scene_.camera.colour = glm::dvec3(0.0);
    scene_.camera.span = open.start;
  }

  void finishLight(const OpenBlock& open) {
    if (!requireProperties(open, {"LOCATION", "COLOUR"}) || !open.valuesOk) return;
    Light light;
    light.matrix[3] = glm::dvec4(open.vectors[0], 1.0);
    light.colour = open.vectors[1];
    light.span = open.start;
    scene_.lights.push_back(light);
  }

  void finishObject() {
    Object& object = *object_;
    std::size_t before = out_.errorCount();
    std::optional<std::size_t> overflow;
    object.matrix = composeTransform(*object.transforms, overflow);
    if (overflow) {
      // A chain of finite SCALEs or TRANSLATEs can still overflow: say
      // which operation did it.
      const TransformOp& op = (*object.transforms)[*overflow];
      out_.error(DiagnosticCode::ValueNotFinite, op.span,
                 std::string(transformKindName(op.kind)) +
                     " makes the object's matrix overflow a double (operation " +
                     std::to_string(*overflow + 1) + " of the TRANSFORMATION)")
          .hint = "every entry of the composed matrix must be a finite double";
      return;
    }
    checkObjectMatrix(object.matrix, objectKindName(object.kind),
                      transformStart_ ? *transformStart_ : object.span, out_);
    if (out_.errorCount() == before) scene_.objects.push_back(std::move(object));
  }

  void finish() {
    if (out_.full() || stopped_) return;
    if (!sawContent_) {
      out_.error(DiagnosticCode::MissingOutputFile, SourceSpan{1, 1, 0}, "file is empty")
          .hint = "an instruction file starts with OUTPUT_FILE";
      return;
    }
    while (!stack_.empty()) {
      const OpenBlock& open = stack_.back();
      out_.error(DiagnosticCode::UnclosedBlock, cursor_.endOfLine(),
                 "the file ends inside the " + std::string(blockName(open.block)) +
                     " block opened at line " + std::to_string(open.start.line))
          .notes.push_back({open.start, "the block opens here"});
      closeTop(false);
    }
    if (!cameraSpan_) {
      out_.error(DiagnosticCode::MissingCamera, cursor_.endOfLine(),
                 "instruction file has no CAMERA block");
    }
    if (!out_.hasErrors()) checkSceneLevel(scene_, out_);
  }

  LineCursor cursor_;
  const ReadOptions& options_;
  Scene& scene_;
  DiagnosticList& out_;
  std::vector<OpenBlock> stack_;
  std::optional<Object> object_;
  std::optional<SourceSpan> transformStart_;
  std::optional<SourceSpan> cameraSpan_;
  SourceSpan lookAtSpan_;
  bool sawContent_ = false;
  // START OBJECT and START LIGHT lines so far, against maxObjects.
  std::size_t objectsSeen_ = 0;
  bool stopped_ = false;  // past maxObjects, or asked to stop: nothing more is read
  // Asked to stop is looked at every few thousand lines (ReadOptions::stop).
  static constexpr std::uint32_t kLinesPerStopCheck = 4096;
  std::uint32_t linesSinceStopCheck_ = kLinesPerStopCheck - 1;
  std::optional<std::string> skipping_;  // the unknown block being skipped
};

}  // namespace

std::span<const std::string_view> instructionBlockNames() { return kBlockNames; }

std::span<const std::string_view> instructionLineKeywords() { return kLineKeywords; }

std::vector<InstructionProperty> instructionProperties() {
  std::vector<InstructionProperty> out;
  for (const PropertyRule& rule : kProperties) {
    out.push_back({rule.keyword, blockName(rule.block), rule.count});
  }
  return out;
}

ReadResult parseInstructionFile(std::string_view text, std::string fileName,
                                const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
  InstructionParser(text, options, result).run();
  return result;
}

}  // namespace scene
