// The scene builder's state and its response to keys and the mouse, apart
// from any window: main.cpp turns GLFW's callbacks into these calls, and the
// unit tests make them directly.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "renderer/render_settings.h"
#include "scenefile/scene.h"
#include "tools/common/tool_failure.h"
#include "tools/sfbuild/scene_history.h"

namespace sfbuild {

// The keys the builder knows, independent of GLFW's codes. Letters and
// digits are their upper-case ASCII characters.
enum Key : int {
  kKeyEnter = 256,
  kKeyEscape,
  kKeyBackspace,
  kKeyToggleIdView,  // F9: each object in a flat colour of its own (tests)
  kKeyUndo,          // Ctrl+Z
  kKeyRedo,          // Ctrl+Shift+Z, Ctrl+Y
  kKeyToggleHelp,    // F1, as H
  kKeySaveAs,        // Ctrl+S: asks for a file name
  kKeyOpen,          // Ctrl+O: asks for a file name
};

// The file name the window is asking for, if any (Ctrl+S, Ctrl+O).
enum class FilePrompt { None, SaveAs, Open };

enum class MouseButton { Left, Right, Middle };

enum class Operation { None, Grab, Rotate, Scale };
// All: a scale on every axis (S alone).
enum class Axis { None, X, Y, Z, All };

struct Selection {
  bool light = false;
  std::size_t index = 0;
  friend bool operator==(const Selection&, const Selection&) = default;
};

// The builder's view, and the CAMERA it saves.
inline constexpr double kVerticalFovDegrees = 60.0;
inline constexpr double kLightRadius = 0.15;     // how big a light is drawn and picked
inline constexpr float kPlaneHalfSize = 500.0f;  // the infinite PLANE as drawn

struct BuilderState {
  scene::Scene scene;
  std::optional<Selection> selection;

  // A transform in progress: the operation, its axis (None while the axis
  // key is awaited), what the user typed, and the matrix before it began.
  Operation operation = Operation::None;
  Axis axis = Axis::None;
  std::string typed;
  glm::dmat4 original{1.0};
  double startMouseX = 0.0;

  // The window, in pixels, and the mouse.
  int width = 640;
  int height = 480;
  glm::dvec2 mouse{0.0};
  bool panning = false;  // middle button held
  bool looking = false;  // right button held
  bool rightMoved = false;

  // Saving: the next number to try, and the last file written (or the
  // reason it failed).
  int nextSaveNumber = 1;
  std::string lastSave;
  // Counts the saves tried, so that the program can tell each of them once.
  std::uint64_t saveAttempts = 0;
  bool idView = false;
  bool showHelp = false;
  // T: the renderer's picture of the view instead of OpenGL's; the window
  // renders it (progressive_render.h) and says how far it has got.
  bool rayTraced = false;
  std::string renderStatus;
  FilePrompt filePrompt = FilePrompt::None;
  // Set by the panels once the prompt's field takes the keys: from then on
  // the title asks for the name (what a script waits for before typing).
  bool filePromptTyping = false;
  // Enter (true) or Escape (false) pressed while the prompt is up, from the
  // window's key queue: Dear ImGui 1.86 reads keys once a frame and misses a
  // press and release between two frames, and a script presses fast.
  std::optional<bool> filePromptAnswer;
  // The file last opened or saved with Ctrl+S: the one file Ctrl+S may
  // write over.
  std::string currentFile;

  // Every change to `scene` that is finished (not a transform in progress,
  // not a drag of the view) becomes a step of the history: recordChange.
  SceneHistory history;
};

// The builder's opening state: an empty scene and the start camera.
BuilderState initialState(int width, int height);
// A state that edits `scene`, its camera included.
BuilderState stateForScene(scene::Scene scene, int width, int height);

// What a saving key press asks of the outside world: whether a file exists,
// and writing one. A failure's message is the reason alone (file_io.h).
struct FileSystem {
  std::function<bool(const std::string&)> exists;
  std::function<tools::MaybeFailure(const std::string& name, const std::string& content)> write;
  // The file's bytes (Ctrl+O).
  std::function<tools::Outcome<std::string>(const std::string& name)> read;
};

// Each of these records what it changed in the history.
void handleKey(BuilderState& state, int key, const FileSystem& files);
void handleMouseButton(BuilderState& state, MouseButton button, bool pressed, double x, double y);
void handleMouseMove(BuilderState& state, double x, double y);
void handleScroll(BuilderState& state, double offset);

// Makes the scene as it is now a step of the history, unless a transform or
// a drag of the view is under way (then its end does). What edits
// state.scene from outside (the panels) calls it once the edit is done.
void recordChange(BuilderState& state);
// Ctrl+Z and Ctrl+Shift+Z: a transform in progress is cancelled first; the
// selection is kept where it still names something.
void undo(BuilderState& state);
void redo(BuilderState& state);

// P: the scene as the next free Scene<n>.sf; returns the name written, or
// nothing (the reason in state.lastSave).
std::optional<std::string> saveScene(BuilderState& state, const FileSystem& files);

// The object or light under window position (x, y), by the renderer's own
// intersection code; lights count as spheres of kLightRadius.
std::optional<Selection> pick(const BuilderState& state, double x, double y);

// The amount a transform in progress applies: the typed number, or one that
// follows the mouse (units, degrees, factor).
double currentAmount(const BuilderState& state);
// The matrix of `op` along `axis` by `amount`, to compose on the right.
glm::dmat4 operationMatrix(Operation op, Axis axis, double amount);

// The vertical field of view sfrender gives the scene: a POV-Ray or glTF
// camera's own, else kVerticalFovDegrees (what --fov defaults to). The
// builder's view and its ray-traced view both use it.
double verticalFovDegrees(const BuilderState& state);
// sfrender's settings for the window's size and that field of view (its
// other defaults: depth 5, seed 0, 1 spp): what the ray-traced view renders.
render::RenderSettings viewRenderSettings(const BuilderState& state);

// The camera-to-world matrix of the view (the CAMERA record), and the
// matrices OpenGL draws with: they match render::PinholeCamera exactly.
glm::dmat4 viewMatrix(const BuilderState& state);
glm::dmat4 projectionMatrix(const BuilderState& state, double near, double far);

// The edits of the properties panel, each recorded in the history: an
// object's placement as the instruction file writes it (M = T Rz Ry Rx S,
// angles in degrees), its material, a light, the camera by eye and look-at
// point (the look-at point must differ from the eye). An index past the end
// does nothing.
void setObjectTransform(BuilderState& state, std::size_t index, const glm::dvec3& translation,
                        const glm::dvec3& rotationDegrees, const glm::dvec3& scale);
void setObjectMaterial(BuilderState& state, std::size_t index, const scene::Material& material);
void setLight(BuilderState& state, std::size_t index, const glm::dvec3& position,
              const glm::dvec3& colour);
void setCameraView(BuilderState& state, const glm::dvec3& eye, const glm::dvec3& lookAt);

// What the builder is doing: "ready", "move: press X, Y or Z",
// "move X 1.5_ units" (the status line, and the title).
std::string modeText(const BuilderState& state);
std::string windowTitle(const BuilderState& state);
// The key list that H (or F1) shows and hides.
const std::vector<std::string>& helpLines();

// The flat colour of object `index` in the id view, 8 bits a channel, and
// back (-1 for the background or a colour no object has).
glm::ivec3 idColour(std::size_t index);
int idFromColour(int r, int g, int b);

}  // namespace sfbuild
