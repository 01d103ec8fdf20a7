#include "tools/sfbuild/builder_state.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "renderer/camera.h"
#include "renderer/render_scene.h"
#include "scenefile/convert.h"
#include "scenefile/matrix.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"
#include "tools/sfbuild/placement.h"

namespace sfbuild {
namespace {

constexpr double kLookRadiansPerPixel = 0.005;
constexpr double kPanUnitsPerPixel = 0.01;
constexpr double kWheelUnitsPerStep = 0.5;
constexpr double kGrabUnitsPerPixel = 0.01;
constexpr double kRotateDegreesPerPixel = 0.5;
constexpr double kScaleDoublingPixels = 200.0;

const glm::dvec3 kRed{1.0, 0.0, 0.0};

glm::dmat4* selectedMatrix(BuilderState& state) {
  if (!state.selection) return nullptr;
  if (state.selection->light) {
    if (state.selection->index >= state.scene.lights.size()) return nullptr;
    return &state.scene.lights[state.selection->index].matrix;
  }
  if (state.selection->index >= state.scene.objects.size()) return nullptr;
  return &state.scene.objects[state.selection->index].matrix;
}

void setSelectedMatrix(BuilderState& state, const glm::dmat4& m) {
  glm::dmat4* target = selectedMatrix(state);
  if (!target) return;
  *target = m;
  // The matrix no longer is the composition of an instruction file's list.
  if (!state.selection->light) state.scene.objects[state.selection->index].transforms.reset();
}

std::optional<double> typedNumber(const std::string& typed) {
  double value = 0.0;
  const char* end = typed.data() + typed.size();
  auto [ptr, ec] = std::from_chars(typed.data(), end, value);
  if (typed.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) return {};
  return value;
}

// The camera as the renderer draws it: the frame in which sfbuild moves it
// and sets up its OpenGL view.
render::PinholeCamera viewCamera(const BuilderState& state) {
  return render::PinholeCamera(state.scene.camera, viewRenderSettings(state));
}

void updatePreview(BuilderState& state) {
  if (state.operation == Operation::None || state.axis == Axis::None) return;
  setSelectedMatrix(
      state, state.original * operationMatrix(state.operation, state.axis, currentAmount(state)));
}

void beginOperation(BuilderState& state, Operation op) {
  glm::dmat4* m = selectedMatrix(state);
  if (!m) return;
  state.operation = op;
  state.axis = op == Operation::Scale ? Axis::All : Axis::None;
  state.typed.clear();
  state.original = *m;
  state.startMouseX = state.mouse.x;
}

void cancelOperation(BuilderState& state) {
  if (state.operation == Operation::None) return;
  setSelectedMatrix(state, state.original);
  state.operation = Operation::None;
  state.axis = Axis::None;
  state.typed.clear();
}

// Applies the amount; a scale by 0 would collapse the object and is refused.
void confirmOperation(BuilderState& state) {
  if (state.operation == Operation::None || state.axis == Axis::None) return;
  double amount = currentAmount(state);
  if (state.operation == Operation::Scale && std::abs(amount) < 1e-9) return;
  updatePreview(state);
  state.operation = Operation::None;
  state.axis = Axis::None;
  state.typed.clear();
}

void addObject(BuilderState& state, scene::ObjectKind kind) {
  scene::Object object;
  object.kind = kind;
  object.material.colour = kRed;
  object.matrix = placedObjectMatrix(kind, state.scene.camera);
  state.scene.objects.push_back(object);
  state.selection = Selection{false, state.scene.objects.size() - 1};
}

void addLight(BuilderState& state) {
  scene::Light light;
  light.matrix[3] = glm::dvec4(placedLightPosition(state.scene), 1.0);
  state.scene.lights.push_back(light);
  state.selection = Selection{true, state.scene.lights.size() - 1};
}

void deleteSelection(BuilderState& state) {
  if (!selectedMatrix(state)) return;
  if (state.selection->light) {
    state.scene.lights.erase(state.scene.lights.begin() +
                             static_cast<std::ptrdiff_t>(state.selection->index));
  } else {
    state.scene.objects.erase(state.scene.objects.begin() +
                              static_cast<std::ptrdiff_t>(state.selection->index));
  }
  state.selection.reset();
}

void colourSelection(BuilderState& state, const glm::dvec3& colour) {
  if (!state.selection || state.selection->light || !selectedMatrix(state)) return;
  state.scene.objects[state.selection->index].material.colour = colour;
}

void setCamera(BuilderState& state, const glm::dvec3& eye, const glm::dvec3& forward) {
  state.scene.camera.matrix = scene::cameraFromLookAt(eye, eye + forward);
  state.scene.camera.lookAt.reset();
}

const char* operationName(Operation op) {
  switch (op) {
    case Operation::Grab:
      return "move";
    case Operation::Rotate:
      return "rotate";
    case Operation::Scale:
      return "scale";
    case Operation::None:
      break;
  }
  return "";
}

const char* axisName(Axis axis) {
  switch (axis) {
    case Axis::X:
      return "X";
    case Axis::Y:
      return "Y";
    case Axis::Z:
      return "Z";
    case Axis::All:
      return "all axes";
    case Axis::None:
      break;
  }
  return "";
}

// A key during a grab, rotation or scale: the axis, the amount typed, or
// the operation confirmed or cancelled.
void handleOperationKey(BuilderState& state, int key) {
  switch (key) {
    case kKeyEscape:
      cancelOperation(state);
      return;
    case kKeyEnter:
      confirmOperation(state);
      return;
    case 'X':
      state.axis = Axis::X;
      break;
    case 'Y':
      state.axis = Axis::Y;
      break;
    case 'Z':
      state.axis = Axis::Z;
      break;
    case kKeyBackspace:
      if (!state.typed.empty()) state.typed.pop_back();
      break;
    default:
      if (state.axis != Axis::None && ((key >= '0' && key <= '9') || key == '.' || key == '-') &&
          state.typed.size() < 24) {
        state.typed.push_back(static_cast<char>(key));
      }
      break;
  }
  // Changing the axis puts the others back as they were.
  setSelectedMatrix(state, state.original);
  updatePreview(state);
}

void handleKeyUnrecorded(BuilderState& state, int key, const FileSystem& files);
void handleMouseButtonUnrecorded(BuilderState& state, MouseButton button, bool pressed, double x,
                                 double y);

std::string formatAmount(double value) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string();
}

}  // namespace

BuilderState initialState(int width, int height) {
  BuilderState state;
  state.width = width;
  state.height = height;
  state.scene.camera.matrix = scene::cameraFromLookAt({0.0, 3.0, 8.0}, {0.0, 0.0, 0.0});
  state.history = SceneHistory(state.scene);
  return state;
}

BuilderState stateForScene(scene::Scene scene, int width, int height) {
  BuilderState state;
  state.width = width;
  state.height = height;
  state.scene = std::move(scene);
  state.history = SceneHistory(state.scene);
  return state;
}

double currentAmount(const BuilderState& state) {
  if (!state.typed.empty()) {
    auto value = typedNumber(state.typed);
    if (value) return *value;
    return state.operation == Operation::Scale ? 1.0 : 0.0;
  }
  double dx = state.mouse.x - state.startMouseX;
  switch (state.operation) {
    case Operation::Grab:
      return dx * kGrabUnitsPerPixel;
    case Operation::Rotate:
      return dx * kRotateDegreesPerPixel;
    case Operation::Scale:
      return std::exp2(dx / kScaleDoublingPixels);
    case Operation::None:
      break;
  }
  return 0.0;
}

glm::dmat4 operationMatrix(Operation op, Axis axis, double amount) {
  glm::dvec3 direction{0.0};
  if (axis == Axis::X) direction.x = 1.0;
  if (axis == Axis::Y) direction.y = 1.0;
  if (axis == Axis::Z) direction.z = 1.0;
  glm::dmat4 m{1.0};
  switch (op) {
    case Operation::Grab:
      m[3] = glm::dvec4(direction * amount, 1.0);
      break;
    case Operation::Rotate: {
      if (axis == Axis::All || axis == Axis::None) break;
      double a = amount * std::numbers::pi / 180.0;
      double c = std::cos(a), s = std::sin(a);
      // FORMATS.md's ROTATE_X/Y/Z, written column by column.
      int i = axis == Axis::X ? 1 : axis == Axis::Y ? 2 : 0;
      int j = axis == Axis::X ? 2 : axis == Axis::Y ? 0 : 1;
      m[i][i] = c;
      m[j][j] = c;
      m[i][j] = s;   // column i, row j
      m[j][i] = -s;  // column j, row i
      break;
    }
    case Operation::Scale:
      for (int k = 0; k < 3; ++k) {
        if (axis == Axis::All || direction[k] != 0.0) m[k][k] = amount;
      }
      break;
    case Operation::None:
      break;
  }
  return m;
}

void handleKey(BuilderState& state, int key, const FileSystem& files) {
  handleKeyUnrecorded(state, key, files);
  recordChange(state);
}

void recordChange(BuilderState& state) {
  if (state.operation != Operation::None || state.looking || state.panning) return;
  state.history.record(state.scene);
}

namespace {
void restore(BuilderState& state, const scene::Scene* snapshot) {
  if (!snapshot) return;
  state.scene = *snapshot;
  if (state.selection && !selectedMatrix(state)) state.selection.reset();
}
}  // namespace

void undo(BuilderState& state) {
  cancelOperation(state);
  recordChange(state);
  restore(state, state.history.undo());
}

void redo(BuilderState& state) {
  cancelOperation(state);
  recordChange(state);
  restore(state, state.history.redo());
}

namespace {
void handleKeyUnrecorded(BuilderState& state, int key, const FileSystem& files) {
  if (key == kKeyUndo) {
    undo(state);
    return;
  }
  if (key == kKeyRedo) {
    redo(state);
    return;
  }
  if (key == kKeyToggleIdView) {
    state.idView = !state.idView;
    return;
  }
  if (state.operation != Operation::None) {
    handleOperationKey(state, key);
    return;
  }
  switch (key) {
    case '1':
      addObject(state, scene::ObjectKind::Plane);
      break;
    case '2':
      addObject(state, scene::ObjectKind::Cube);
      break;
    case '3':
      addObject(state, scene::ObjectKind::Sphere);
      break;
    case '4':
      addObject(state, scene::ObjectKind::Cylinder);
      break;
    case 'L':
      addLight(state);
      break;
    case 'X':
      deleteSelection(state);
      break;
    case 'G':
      beginOperation(state, Operation::Grab);
      break;
    case 'R':
      beginOperation(state, Operation::Rotate);
      break;
    case 'S':
      beginOperation(state, Operation::Scale);
      break;
    case 'V':
      colourSelection(state, {1.0, 0.0, 0.0});
      break;
    case 'B':
      colourSelection(state, {0.0, 1.0, 0.0});
      break;
    case 'N':
      colourSelection(state, {0.0, 0.0, 1.0});
      break;
    case 'M':
      colourSelection(state, {0.5, 0.0, 0.5});
      break;
    case 'P':
      saveScene(state, files);
      break;
    case 'T':
      state.rayTraced = !state.rayTraced;
      break;
    case kKeySaveAs:
      state.filePrompt = FilePrompt::SaveAs;
      break;
    case kKeyOpen:
      state.filePrompt = FilePrompt::Open;
      break;
    case 'H':
    case kKeyToggleHelp:
      state.showHelp = !state.showHelp;
      break;
    case kKeyEscape:
      state.selection.reset();
      break;
    default:
      break;
  }
}

}  // namespace

void handleMouseButton(BuilderState& state, MouseButton button, bool pressed, double x, double y) {
  handleMouseButtonUnrecorded(state, button, pressed, x, y);
  recordChange(state);
}

namespace {
void handleMouseButtonUnrecorded(BuilderState& state, MouseButton button, bool pressed, double x,
                                 double y) {
  state.mouse = {x, y};
  switch (button) {
    case MouseButton::Left:
      if (!pressed) return;
      if (state.operation != Operation::None) {
        confirmOperation(state);
      } else {
        state.selection = pick(state, x, y);
      }
      return;
    case MouseButton::Right:
      if (pressed && state.operation != Operation::None) {
        cancelOperation(state);
        return;
      }
      state.looking = pressed;
      return;
    case MouseButton::Middle:
      state.panning = pressed;
      return;
  }
}

}  // namespace

void handleMouseMove(BuilderState& state, double x, double y) {
  glm::dvec2 delta = glm::dvec2(x, y) - state.mouse;
  state.mouse = {x, y};
  if (state.looking || state.panning) {
    render::PinholeCamera camera = viewCamera(state);
    if (state.looking) {
      // Yaw about world +Y, pitch about the camera's right, kept off the poles.
      double yaw = -delta.x * kLookRadiansPerPixel;
      double pitch = -delta.y * kLookRadiansPerPixel;
      glm::dvec3 forward = glm::dvec3(glm::rotate(glm::dmat4(1.0), yaw, glm::dvec3(0, 1, 0)) *
                                      glm::rotate(glm::dmat4(1.0), pitch, camera.right()) *
                                      glm::dvec4(camera.forward(), 0.0));
      forward = glm::normalize(forward);
      if (std::abs(forward.y) < 0.99) setCamera(state, camera.eye(), forward);
    } else {
      glm::dvec3 eye =
          camera.eye() + (-delta.x * camera.right() + delta.y * camera.up()) * kPanUnitsPerPixel;
      setCamera(state, eye, camera.forward());
    }
  }
  if (state.operation != Operation::None && state.typed.empty()) updatePreview(state);
}

void handleScroll(BuilderState& state, double offset) {
  render::PinholeCamera camera = viewCamera(state);
  setCamera(state, camera.eye() + camera.forward() * (offset * kWheelUnitsPerStep),
            camera.forward());
  recordChange(state);
}

std::optional<std::string> saveScene(BuilderState& state, const FileSystem& files) {
  ++state.saveAttempts;
  int n = std::max(state.nextSaveNumber, 1);
  std::string name;
  for (;; ++n) {
    name = "Scene" + std::to_string(n) + ".sf";
    if (!files.exists(name)) break;
  }
  // The scene file's own writer, through the registry: what a scene file
  // cannot hold (an instruction file's materials) is dropped, as it always
  // was; only a scene with a number that is not finite cannot be written.
  scene::DiagnosticList losses;
  std::optional<std::string> text =
      scene::convertScene(state.scene, scene::Format::SceneFile, {}, losses);
  if (!text) {
    state.lastSave = "could not save " + name + ": the scene holds a value that is not finite";
    return {};
  }
  if (tools::MaybeFailure failure = files.write(name, *text)) {
    state.lastSave = "could not save " + name + ": " + failure->message;
    return {};
  }
  state.nextSaveNumber = n + 1;
  state.lastSave = "saved " + name;
  return name;
}

std::optional<Selection> pick(const BuilderState& state, double x, double y) {
  // The objects, then one sphere per light, in one scene for the renderer.
  scene::Scene pickScene;
  pickScene.camera = state.scene.camera;
  pickScene.objects = state.scene.objects;
  for (const scene::Light& light : state.scene.lights) {
    scene::Object sphere;
    sphere.kind = scene::ObjectKind::Sphere;
    sphere.matrix =
        glm::scale(glm::translate(glm::dmat4(1.0), light.position()), glm::dvec3(kLightRadius));
    pickScene.objects.push_back(sphere);
  }
  // One ray, no shadows: no lights' grids.
  render::RenderScene renderScene(pickScene, 0, false);
  render::PinholeCamera camera(renderScene.camera(), viewRenderSettings(state));
  auto hit = renderScene.closestHit(camera.rayThrough(x, y), render::RaySource{});
  if (!hit) return {};
  std::size_t objects = state.scene.objects.size();
  std::size_t picked = renderScene.sceneObject(hit->object);
  if (picked < objects) return Selection{false, picked};
  return Selection{true, picked - objects};
}

double verticalFovDegrees(const BuilderState& state) {
  // As scene::applySceneView, which --width and --height both given
  // leave the aspect ratio to.
  if (state.scene.view) {
    return std::clamp(state.scene.view->verticalFovDegrees, scene::kMinFovDegrees,
                      scene::kMaxFovDegrees);
  }
  return kVerticalFovDegrees;
}

render::RenderSettings viewRenderSettings(const BuilderState& state) {
  render::RenderSettings settings;
  settings.width = state.width;
  settings.height = state.height;
  settings.verticalFovDegrees = verticalFovDegrees(state);
  return settings;
}

glm::dmat4 viewMatrix(const BuilderState& state) {
  render::PinholeCamera camera = viewCamera(state);
  glm::dmat4 view(1.0);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = camera.right()[c];
    view[c][1] = camera.up()[c];
    view[c][2] = -camera.forward()[c];
  }
  view[3][0] = -glm::dot(camera.right(), camera.eye());
  view[3][1] = -glm::dot(camera.up(), camera.eye());
  view[3][2] = glm::dot(camera.forward(), camera.eye());
  return view;
}

glm::dmat4 projectionMatrix(const BuilderState& state, double near, double far) {
  // x_ndc = (r.d / f.d) / tanHalfWidth: the pinhole of render::PinholeCamera,
  // whose pixel (i, j) centre is OpenGL's fragment centre too.
  double tanHalfHeight = viewCamera(state).tanHalfHeight();
  double aspect = static_cast<double>(state.width) / state.height;
  glm::dmat4 p(0.0);
  p[0][0] = 1.0 / (tanHalfHeight * aspect);
  p[1][1] = 1.0 / tanHalfHeight;
  p[2][2] = -(far + near) / (far - near);
  p[2][3] = -1.0;
  p[3][2] = -2.0 * far * near / (far - near);
  return p;
}

std::string windowTitle(const BuilderState& state) {
  std::string title = "sfbuild | " + modeText(state);
  title += " | ";
  if (!state.selection) {
    title += "nothing selected";
  } else if (state.selection->light) {
    title += "LIGHT " + std::to_string(state.selection->index + 1);
  } else if (state.selection->index < state.scene.objects.size()) {
    title += std::string(scene::objectKindName(state.scene.objects[state.selection->index].kind)) +
             " " + std::to_string(state.selection->index + 1);
  }
  if (state.rayTraced) title += " | " + state.renderStatus;
  if (!state.lastSave.empty()) title += " | " + state.lastSave;
  if (!state.showHelp) title += " | H: keys";
  return title;
}

void setObjectTransform(BuilderState& state, std::size_t index, const glm::dvec3& translation,
                        const glm::dvec3& rotationDegrees, const glm::dvec3& scale) {
  if (index >= state.scene.objects.size()) return;
  std::vector<scene::TransformOp> ops;
  auto add = [&ops](scene::TransformKind kind, const glm::dvec3& value) {
    scene::TransformOp op;
    op.kind = kind;
    op.value = value;
    ops.push_back(op);
  };
  constexpr double kRadians = std::numbers::pi / 180.0;
  add(scene::TransformKind::Scale, scale);
  add(scene::TransformKind::RotateX, glm::dvec3(rotationDegrees.x * kRadians, 0, 0));
  add(scene::TransformKind::RotateY, glm::dvec3(rotationDegrees.y * kRadians, 0, 0));
  add(scene::TransformKind::RotateZ, glm::dvec3(rotationDegrees.z * kRadians, 0, 0));
  add(scene::TransformKind::Translate, translation);
  cancelOperation(state);
  state.scene.objects[index].matrix = scene::composeTransform(ops);
  state.scene.objects[index].transforms.reset();
  recordChange(state);
}

void setObjectMaterial(BuilderState& state, std::size_t index, const scene::Material& material) {
  if (index >= state.scene.objects.size()) return;
  state.scene.objects[index].material = material;
  recordChange(state);
}

void setLight(BuilderState& state, std::size_t index, const glm::dvec3& position,
              const glm::dvec3& colour) {
  if (index >= state.scene.lights.size()) return;
  cancelOperation(state);
  state.scene.lights[index].matrix[3] = glm::dvec4(position, 1.0);
  state.scene.lights[index].colour = colour;
  recordChange(state);
}

void setCameraView(BuilderState& state, const glm::dvec3& eye, const glm::dvec3& lookAt) {
  if (eye == lookAt) return;
  state.scene.camera.matrix = scene::cameraFromLookAt(eye, lookAt);
  state.scene.camera.lookAt.reset();
  recordChange(state);
}

std::string modeText(const BuilderState& state) {
  std::string title;
  if (state.filePrompt != FilePrompt::None && state.filePromptTyping) {
    title += state.filePrompt == FilePrompt::SaveAs ? "save as: type a file name"
                                                    : "open: type a file name";
  } else if (state.operation == Operation::None) {
    title += "ready";
  } else if (state.axis == Axis::None) {
    title += std::string(operationName(state.operation)) + ": press X, Y or Z";
  } else {
    title += std::string(operationName(state.operation)) + " " + axisName(state.axis) + " " +
             (state.typed.empty() ? formatAmount(currentAmount(state)) : state.typed + "_");
    title += state.operation == Operation::Grab     ? " units"
             : state.operation == Operation::Rotate ? " degrees"
                                                    : " times";
  }
  return title;
}

const std::vector<std::string>& helpLines() {
  static const std::vector<std::string> lines = {
      "1 plane  2 cube  3 sphere  4 cylinder  L light (where the camera looks)",
      "X delete the selection",
      "G / R / S then X, Y or Z: move, rotate, scale on the object's axis",
      "S alone: scale on all axes",
      "type a number, Enter: exact amount; Esc: cancel",
      "V red  B green  N blue  M purple",
      "P save Scene<n>.sf  Ctrl+S save as (.sf, .txt ...)  Ctrl+O open",
      "T ray-traced view (sfrender's picture, refined as it renders)",
      "Ctrl+Z undo  Ctrl+Shift+Z or Ctrl+Y redo",
      "F9 id view (each object in a flat colour)",
      "left click select; middle drag pan; right drag look; wheel forward",
      "H or F1 show or hide this list",
  };
  return lines;
}

glm::ivec3 idColour(std::size_t index) {
  std::size_t n = index + 1;
  return {static_cast<int>(n & 255), static_cast<int>((n >> 8) & 255), 200};
}

int idFromColour(int r, int g, int b) {
  if (b != 200) return -1;
  int n = r + 256 * g;
  return n == 0 ? -1 : n - 1;
}

}  // namespace sfbuild
