#include "scenefile/keywords.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "libscene/formats/instruction/instruction_reader.h"
#include "libscene/formats/sf/sf_reader.h"

namespace scene {
namespace {

using Words = std::set<std::string_view>;

Words wordsAt(Format format, std::initializer_list<KeywordPlace> places) {
  Words out;
  for (KeywordPlace place : places) {
    for (const KeywordInfo* k : keywordsAt(format, place)) out.insert(k->word);
  }
  return out;
}

template <typename Range>
Words asSet(const Range& range) {
  return Words(std::begin(range), std::end(range));
}

KeywordPlace placeOfBlock(std::string_view block) {
  if (block == "CAMERA") return KeywordPlace::Camera;
  if (block == "LIGHT") return KeywordPlace::Light;
  if (block == "MATERIAL") return KeywordPlace::Material;
  return KeywordPlace::Transformation;
}

std::size_t argumentCount(std::string_view arguments) {
  return arguments.empty() ? 0 : 1 + std::count(arguments.begin(), arguments.end(), ' ');
}

// The table holds exactly the words the readers accept, each where the
// readers accept it.
TEST(Keywords, TheSceneFileReadersRecordNamesAndNothingElse) {
  EXPECT_EQ(wordsAt(Format::SceneFile, {KeywordPlace::Record}), asSet(sceneFileRecordNames()));
  std::size_t sceneFileRows = 0;
  for (const KeywordInfo& k : keywords()) sceneFileRows += k.format == Format::SceneFile;
  EXPECT_EQ(sceneFileRows, sceneFileRecordNames().size());
}

TEST(Keywords, TheInstructionReadersWordsEachAtItsPlace) {
  using P = KeywordPlace;
  // Every property where the reader takes it, with as many numbers.
  std::size_t properties = 0;
  for (const InstructionProperty& property : instructionProperties()) {
    SCOPED_TRACE(std::string(property.keyword) + " in " + std::string(property.block));
    const KeywordInfo* k =
        findKeyword(property.keyword, Format::InstructionFile, placeOfBlock(property.block));
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(argumentCount(k->arguments), static_cast<std::size_t>(property.count));
    ++properties;
  }
  Words blockBodies =
      wordsAt(Format::InstructionFile, {P::Camera, P::Light, P::Material, P::Transformation});
  std::size_t bodyRows = 0;
  for (P place : {P::Camera, P::Light, P::Material, P::Transformation}) {
    bodyRows += keywordsAt(Format::InstructionFile, place).size();
    EXPECT_NE(findKeyword("END", Format::InstructionFile, place), nullptr);
  }
  EXPECT_EQ(bodyRows, properties + 4);  // and END in each
  EXPECT_EQ(wordsAt(Format::InstructionFile, {P::Object}), (Words{"START", "END"}));

  // Every word a line may start with, and only those.
  EXPECT_EQ(wordsAt(Format::InstructionFile,
                    {P::TopLevel, P::Camera, P::Light, P::Object, P::Material, P::Transformation}),
            asSet(instructionLineKeywords()));
  // The block names after START, the sections' inside an OBJECT only.
  EXPECT_EQ(wordsAt(Format::InstructionFile, {P::BlockName, P::SectionName}),
            asSet(instructionBlockNames()));
  EXPECT_EQ(wordsAt(Format::InstructionFile, {P::SectionName}),
            (Words{"MATERIAL", "TRANSFORMATION"}));
  Words kinds;
  for (ObjectKind kind : kObjectKinds) kinds.insert(objectKindName(kind));
  EXPECT_EQ(wordsAt(Format::InstructionFile, {P::ObjectKindName}), kinds);
}

TEST(Keywords, EachRowOnceWithAMeaning) {
  std::set<std::tuple<std::string_view, Format, KeywordPlace>> seen;
  for (const KeywordInfo& k : keywords()) {
    EXPECT_TRUE(seen.insert({k.word, k.format, k.place}).second) << k.word;
    EXPECT_FALSE(k.meaning.empty()) << k.word;
    EXPECT_EQ(findKeyword(k.word, k.format, k.place), &k);
  }
  EXPECT_EQ(findKeyword("sphere", Format::SceneFile, KeywordPlace::Record), nullptr);
  EXPECT_EQ(findKeyword("SPHERE", Format::Pov, KeywordPlace::Record), nullptr);
}

TEST(Keywords, RangesAreTheValidatorsRanges) {
  auto range = [](std::string_view word) {
    return findKeyword(word, Format::InstructionFile, KeywordPlace::Material)->range;
  };
  for (std::string_view unit : {"AMBIENT", "DIFFUSE", "SPECULAR", "REFLECTIVITY", "TRANSPARENCY"}) {
    EXPECT_EQ(range(unit), "0 to 1") << unit;
  }
  EXPECT_EQ(range("SHININESS"), "above 0");
  EXPECT_EQ(range("RI"), "above 0 (below 1 draws a warning)");
  EXPECT_EQ(findKeyword("SCALE", Format::InstructionFile, KeywordPlace::Transformation)->range,
            "any factor but 0");
}

TEST(MatrixEntryMeaning, SaysWhatEachEntryIsForEachRecord) {
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Object, 2, 4), "translation along y");
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Object, 3, 1),
            "the world z of the local x axis (rotation, scale, shear)");
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Camera, 1, 4), "the eye's x");
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Camera, 2, 3),
            "the backward axis's y (the camera looks the opposite way)");
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Light, 1, 1), "ignored");
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Light, 3, 4), "the light's z");
  for (OutlineKind kind : {OutlineKind::Camera, OutlineKind::Light, OutlineKind::Object}) {
    EXPECT_EQ(matrixEntryMeaning(kind, 4, 1), "must be 0");
    EXPECT_EQ(matrixEntryMeaning(kind, 4, 4), "must be 1");
    EXPECT_EQ(matrixEntryMeaning(kind, 0, 1), "");
    EXPECT_EQ(matrixEntryMeaning(kind, 1, 5), "");
  }
  EXPECT_EQ(matrixEntryMeaning(OutlineKind::Material, 1, 1), "");
}

}  // namespace
}  // namespace scene
