#include "tools/sfbuild/panels.h"

#include <imgui.h>

#include <numbers>
#include <string>

#include "scenefile/transform.h"
#include "tools/sfbuild/scene_files.h"

namespace sfbuild {
namespace {

constexpr float kSceneWidth = 220.0f;
constexpr float kSceneHeight = 170.0f;
constexpr float kHelpWidth = 330.0f;
constexpr float kHelpHeight = 230.0f;
constexpr float kStatusHeight = 22.0f;
constexpr float kPromptWidth = 420.0f;
constexpr ImGuiWindowFlags kFixed =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings;
// 15 digits: 0.1 reads 0.1, not 0.10000000000000001. A field not edited
// keeps its double as it is, whatever it shows.
constexpr const char* kNumberFormat = "%.15g";

// Three doubles in one row; true once an edit is done (Enter, or the field
// left after a change), which is when it becomes a step of the history.
bool editTriple(const char* label, glm::dvec3& value) {
  ImGui::InputScalarN(label, ImGuiDataType_Double, &value[0], 3, nullptr, nullptr, kNumberFormat);
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool editNumber(const char* label, double& value) {
  ImGui::InputScalar(label, ImGuiDataType_Double, &value, nullptr, nullptr, kNumberFormat);
  return ImGui::IsItemDeactivatedAfterEdit();
}

std::string objectLabel(const scene::Object& object, std::size_t index) {
  return std::string(scene::objectKindName(object.kind)) + " " + std::to_string(index + 1);
}

}  // namespace

void Panels::draw(BuilderState& state, const FileSystem& files) {
  drawScene(state, 0.0f);
  drawProperties(state, kSceneHeight);
  if (state.showHelp) drawHelp(state);
  drawStatus(state);
  if (state.filePrompt != FilePrompt::None) drawFilePrompt(state, files);
}

void Panels::drawFilePrompt(BuilderState& state, const FileSystem& files) {
  ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.4f), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(kPromptWidth, 0.0f));
  bool saving = state.filePrompt == FilePrompt::SaveAs;
  ImGui::Begin(saving ? "Save as (Enter saves, Esc cancels)" : "Open (Enter opens, Esc cancels)",
               nullptr, kFixed | ImGuiWindowFlags_NoCollapse);
  ImGui::TextDisabled(saving ? ".sf a scene file, .txt an instruction file (materials kept)"
                             : "any format sfrender reads");
  if (!promptFocused_) {
    ImGui::SetKeyboardFocusHere();
    promptFocused_ = true;
  }
  ImGui::PushItemWidth(-1.0f);
  ImGui::InputText("##file name", fileName_.data(), fileName_.size());
  if (ImGui::IsItemActive()) state.filePromptTyping = true;
  ImGui::PopItemWidth();
  ImGui::End();
  if (!state.filePromptAnswer) return;
  if (*state.filePromptAnswer) {
    std::string name(fileName_.data());
    if (saving) {
      saveSceneAs(state, name, files);
    } else {
      openSceneFile(state, name, files);
    }
  }
  state.filePrompt = FilePrompt::None;
  state.filePromptTyping = false;
  state.filePromptAnswer.reset();
  promptFocused_ = false;
  fileName_.fill('\0');  // the next prompt starts empty
}

void Panels::drawScene(BuilderState& state, float top) {
  ImGui::SetNextWindowPos(ImVec2(0.0f, top));
  ImGui::SetNextWindowSize(ImVec2(kSceneWidth, kSceneHeight));
  ImGui::Begin("Scene", nullptr, kFixed);
  if (ImGui::Selectable("CAMERA", cameraShown_ && !state.selection)) {
    cameraShown_ = true;
    state.selection.reset();
  }
  for (std::size_t i = 0; i < state.scene.lights.size(); ++i) {
    Selection s{true, i};
    std::string label = "LIGHT " + std::to_string(i + 1);
    if (ImGui::Selectable(label.c_str(), state.selection == s)) state.selection = s;
  }
  for (std::size_t i = 0; i < state.scene.objects.size(); ++i) {
    Selection s{false, i};
    std::string label = objectLabel(state.scene.objects[i], i);
    if (ImGui::Selectable(label.c_str(), state.selection == s)) state.selection = s;
  }
  if (state.selection) cameraShown_ = false;
  ImGui::End();
}

void Panels::drawProperties(BuilderState& state, float top) {
  float height = ImGui::GetIO().DisplaySize.y - top - kStatusHeight;
  ImGui::SetNextWindowPos(ImVec2(0.0f, top));
  ImGui::SetNextWindowSize(ImVec2(kSceneWidth, height));
  ImGui::Begin("Properties", nullptr, kFixed);
  ImGui::PushItemWidth(-84.0f);  // room for the labels on the right
  if (!state.selection && cameraShown_) {
    scene::LookAtCamera camera = scene::lookAtFromCamera(state.scene.camera.matrix);
    ImGui::TextUnformatted("CAMERA");
    // Every field drawn every frame, whichever was edited.
    bool eyeEdited = editTriple("eye", camera.location);
    bool lookAtEdited = editTriple("look at", camera.lookAt);
    if (eyeEdited || lookAtEdited) {
      setCameraView(state, camera.location, camera.lookAt);
    }
  } else if (state.selection && state.selection->light &&
             state.selection->index < state.scene.lights.size()) {
    std::size_t i = state.selection->index;
    const scene::Light& light = state.scene.lights[i];
    glm::dvec3 position = light.position(), colour = light.colour;
    ImGui::Text("LIGHT %zu", i + 1);
    bool positionEdited = editTriple("position", position);
    bool colourEdited = editTriple("colour", colour);
    if (positionEdited || colourEdited) {
      setLight(state, i, position, colour);
    }
  } else if (state.selection && !state.selection->light &&
             state.selection->index < state.scene.objects.size()) {
    std::size_t i = state.selection->index;
    const scene::Object& object = state.scene.objects[i];
    ImGui::TextUnformatted(objectLabel(object, i).c_str());
    scene::TransformDecomposition d = scene::decomposeTransform(object.matrix);
    glm::dvec3 degrees = d.rotation * (180.0 / std::numbers::pi);
    bool positionEdited = editTriple("position", d.translation);
    bool rotationEdited = editTriple("rotation", degrees);
    bool scaleEdited = editTriple("scale", d.scale);
    if (positionEdited || rotationEdited || scaleEdited) {
      setObjectTransform(state, i, d.translation, degrees, d.scale);
    }
    if (!d.exact()) ImGui::TextDisabled("(sheared: shown as its nearest)");
    scene::Material material = object.material;
    bool changed = editTriple("colour", material.colour);
    ImGui::TextDisabled("material (instruction files)");
    for (scene::MaterialProperty p : scene::kMaterialProperties) {
      std::string name(scene::materialPropertyName(p));
      changed |= editNumber(name.c_str(), scene::materialValue(material, p));
    }
    if (changed) setObjectMaterial(state, i, material);
  } else {
    ImGui::TextDisabled("nothing selected");
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void Panels::drawHelp(BuilderState& state) {
  ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - kHelpWidth, display.y - kStatusHeight - kHelpHeight));
  ImGui::SetNextWindowSize(ImVec2(kHelpWidth, kHelpHeight));
  bool open = true;
  ImGui::Begin("Keys (H or F1)", &open, kFixed);
  for (const std::string& line : helpLines()) ImGui::TextWrapped("%s", line.c_str());
  ImGui::End();
  if (!open) state.showHelp = false;
}

void Panels::drawStatus(const BuilderState& state) {
  ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.0f, display.y - kStatusHeight));
  ImGui::SetNextWindowSize(ImVec2(display.x, kStatusHeight));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6.0f, 3.0f));
  ImGui::Begin("status", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar);
  std::string text = modeText(state);
  if (state.rayTraced) text += "   |   " + state.renderStatus;
  if (!state.lastSave.empty()) text += "   |   " + state.lastSave;
  ImGui::TextUnformatted(text.c_str());
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace sfbuild
