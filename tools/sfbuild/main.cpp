// sfbuild: the interactive scene builder. GLFW's callbacks become calls on
// the BuilderState; GlView draws it.
#include <epoxy/gl.h>
// GLFW after the loader, which brings the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "scenefile/read.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/common/standard_streams.h"
#include "tools/common/tool_output.h"
#include "tools/common/tool_streams.h"
#include "tools/sfbuild/builder_state.h"
#include "tools/sfbuild/gl_view.h"
#include "tools/sfbuild/panels.h"
#include "tools/sfbuild/progressive_render.h"
#include "tools/sfbuild/ray_traced_view.h"
#include "tools/sfbuild/sfbuild_command_line.h"

namespace {

// A key as GLFW's callback gave it, kept for the main loop.
struct KeyPress {
  int key = 0;
  int mods = 0;
};

struct App {
  sfbuild::BuilderState state;
  // Filled by the key callback during glfwWaitEventsTimeout, emptied by the
  // main loop right after, in order: no press is missed or reordered,
  // however long a frame takes (glfwGetKey would only see the state at the
  // time of asking, and miss a press and release between two frames).
  std::vector<KeyPress> pendingKeys;
  sfbuild::FileSystem files;
  std::string title;
  bool quiet = false;
  const tools::ToolOutput* output = nullptr;
  std::uint64_t savesTold = 0;
};

// Says on standard error what the last save did, once: "sfbuild: wrote
// Scene1.sf", or why it could not.
void tellSave(App& app) {
  if (app.state.saveAttempts == app.savesTold || !app.output) return;
  app.savesTold = app.state.saveAttempts;
  const std::string& what = app.state.lastSave;
  if (what.starts_with("saved ")) {
    app.output->info("wrote " + tools::printableText(what.substr(6)));
  } else {
    app.output->error(tools::printableText(what));
  }
}

// The ray-traced view (T): what it renders, to restart when that changes.
struct RayTracing {
  sfbuild::ProgressiveRender renders;
  std::optional<scene::Scene> scene;  // of the render under way
  int width = 0, height = 0;
  bool done = false;
  std::chrono::steady_clock::time_point started;
};

std::string frameStatus(const sfbuild::RenderedFrame& frame) {
  if (!frame.error.empty()) return "ray traced: failed: " + frame.error;
  std::ostringstream text;
  text << "ray traced: level " << frame.level + 1 << " of " << frame.levelCount << ", "
       << frame.width << "x" << frame.height << ", " << frame.settings.samplesPerPixel << " spp";
  if (frame.settings.adaptiveThreshold > 0) {
    text << " adaptive " << frame.settings.adaptiveThreshold;
  }
  if (frame.last()) text << ", done";
  return text.str();
}

// Restarts the render when the scene or the window has changed since it
// began, and shows its newest level; says each level's time with -v.
void drawRayTraced(App& app, RayTracing& rt, sfbuild::RayTracedView& view) {
  sfbuild::BuilderState& state = app.state;
  if (!rt.scene || rt.width != state.width || rt.height != state.height ||
      !(*rt.scene == state.scene)) {
    rt.renders.start(state.scene, sfbuild::viewRenderSettings(state));
    rt.scene = state.scene;
    rt.width = state.width;
    rt.height = state.height;
    rt.done = false;
    rt.started = std::chrono::steady_clock::now();
    state.renderStatus = "ray traced: rendering";
  }
  if (std::optional<sfbuild::RenderedFrame> frame = rt.renders.takeFrame()) {
    view.upload(*frame);
    state.renderStatus = frameStatus(*frame);
    rt.done = frame->last() || !frame->error.empty();
    std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - rt.started;
    std::ostringstream ms;
    ms << std::fixed << std::setprecision(1) << elapsed.count();
    if (app.output) app.output->detail(state.renderStatus + " after " + ms.str() + " ms");
  }
  view.draw(state.width, state.height);
}

void stopRayTracing(RayTracing& rt, sfbuild::RayTracedView& view) {
  if (!rt.scene) return;
  rt.renders.stop();
  rt.scene.reset();
  view.clear();
}

App* appOf(GLFWwindow* window) {
  return static_cast<App*>(glfwGetWindowUserPointer(window));
}

int builderKey(int key, int mods) {
  if (mods & GLFW_MOD_CONTROL) {
    if (key == GLFW_KEY_Z) return (mods & GLFW_MOD_SHIFT) ? sfbuild::kKeyRedo : sfbuild::kKeyUndo;
    if (key == GLFW_KEY_Y) return sfbuild::kKeyRedo;
    if (key == GLFW_KEY_S) return sfbuild::kKeySaveAs;
    if (key == GLFW_KEY_O) return sfbuild::kKeyOpen;
    return -1;  // no other Ctrl combination means anything yet
  }
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) {
    return key;  // GLFW's codes for these are their ASCII characters
  }
  if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) return '0' + (key - GLFW_KEY_KP_0);
  switch (key) {
    case GLFW_KEY_F1:
      return sfbuild::kKeyToggleHelp;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      return '-';
    case GLFW_KEY_PERIOD:
    case GLFW_KEY_KP_DECIMAL:
      return '.';
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
      return sfbuild::kKeyEnter;
    case GLFW_KEY_ESCAPE:
      return sfbuild::kKeyEscape;
    case GLFW_KEY_BACKSPACE:
      return sfbuild::kKeyBackspace;
    case GLFW_KEY_F9:
      return sfbuild::kKeyToggleIdView;
    default:
      return -1;
  }
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
  if (action != GLFW_PRESS && !(action == GLFW_REPEAT && key == GLFW_KEY_BACKSPACE)) return;
  appOf(window)->pendingKeys.push_back({key, mods});
}

// Hands the keys pressed since the last frame to the builder, in order;
// while a text field of the panels has the keyboard, they are its alone.
void handleKeys(App& app) {
  std::vector<KeyPress> keys;
  keys.swap(app.pendingKeys);
  if (app.state.filePrompt != sfbuild::FilePrompt::None) {
    // The name's characters reach the field through ImGui's own queue.
    for (const KeyPress& press : keys) {
      int k = builderKey(press.key, press.mods);
      if (k == sfbuild::kKeyEnter) app.state.filePromptAnswer = true;
      if (k == sfbuild::kKeyEscape) app.state.filePromptAnswer = false;
      if (app.state.filePromptAnswer) break;
    }
    return;
  }
  // WantCaptureKeyboard dates from the start of the last frame: a field
  // that Enter closed during it still counts, and the key pressed right
  // after (Ctrl+O after a name typed in the prompt) would be lost; whether
  // an item is active is how the frame ended.
  if (ImGui::GetIO().WantCaptureKeyboard && ImGui::IsAnyItemActive()) return;
  for (const KeyPress& press : keys) {
    int k = builderKey(press.key, press.mods);
    if (k < 0) continue;
    bool helpBefore = app.state.showHelp;
    sfbuild::handleKey(app.state, k, app.files);
    tellSave(app);
    if (app.state.showHelp && !helpBefore && !app.quiet) {
      for (const std::string& line : sfbuild::helpLines()) std::cout << line << "\n";
      std::cout.flush();
    }
  }
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
  // A press on a panel is the panel's; a release always ends a drag.
  if (action == GLFW_PRESS && ImGui::GetIO().WantCaptureMouse) return;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  sfbuild::MouseButton b;
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    b = sfbuild::MouseButton::Left;
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
    b = sfbuild::MouseButton::Right;
  } else if (button == GLFW_MOUSE_BUTTON_MIDDLE) {
    b = sfbuild::MouseButton::Middle;
  } else {
    return;
  }
  // The pointer at (x, y) sits in the pixel whose centre is (x + 0.5, y + 0.5).
  sfbuild::handleMouseButton(appOf(window)->state, b, action == GLFW_PRESS, x + 0.5, y + 0.5);
}

void onCursor(GLFWwindow* window, double x, double y) {
  sfbuild::handleMouseMove(appOf(window)->state, x + 0.5, y + 0.5);
}

void onScroll(GLFWwindow* window, double, double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  sfbuild::handleScroll(appOf(window)->state, dy);
}

void onFramebufferSize(GLFWwindow* window, int width, int height) {
  if (width <= 0 || height <= 0) return;
  appOf(window)->state.width = width;
  appOf(window)->state.height = height;
}

// Why GLFW's last call failed (glfwGetError), in the house style: lower
// case, no final period ("X11: The DISPLAY environment variable is
// missing." becomes "x11: the DISPLAY environment variable is missing").
std::string glfwReason() {
  const char* description = nullptr;
  glfwGetError(&description);
  std::string reason = description ? description : "";
  while (!reason.empty() && (reason.back() == '.' || reason.back() == '\n')) reason.pop_back();
  auto lower = [&reason](std::size_t at) {
    // Only a capital that starts a word of lower-case letters: DISPLAY stays.
    if (at + 1 < reason.size() && std::isupper(static_cast<unsigned char>(reason[at])) &&
        std::islower(static_cast<unsigned char>(reason[at + 1]))) {
      reason[at] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[at])));
    }
  };
  if (!reason.empty())
    reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
  for (std::size_t at = reason.find(": "); at != std::string::npos;
       at = reason.find(": ", at + 2)) {
    lower(at + 2);
  }
  return reason;
}

// The scene named on the command line, or why it cannot be opened.
tools::MaybeFailure openScene(const sfbuild::SfbuildOptions& o, const tools::ToolOutput& output,
                              App& app) {
  tools::InputText text = tools::readInputText(o.input, o.read, &output.streams().in);
  tools::DiagnosticStyle style = output.diagnosticStyle(tools::DiagnosticFormat::Text);
  if (text.tooLarge()) {
    tools::DiagnosticPrinter(output.err(), style).print(text.diagnostics);
    return tools::toldFailure(tools::ExitCode::InvalidInput);
  }
  std::string shown = tools::inputDisplayName(o.input);
  if (!text.text) {
    return tools::fileFailure(tools::ExitCode::IoError, shown,
                              "cannot read the file: " + tools::printableText(text.readError));
  }
  scene::ReadResult result = scene::parseScene(*text.text, shown, o.read);
  tools::SourceExcerpts sources;
  sources.capture(shown, *text.text, result.diagnostics);
  tools::DiagnosticPrinter(output.err(), style, &sources).print(result.diagnostics);
  if (!result.ok()) return tools::toldFailure(tools::ExitCode::InvalidInput);
  app.state = sfbuild::stateForScene(std::move(result.scene), o.width, o.height);
  return std::nullopt;
}

// The window, or nothing after saying why there is none: no display (or
// none that GLFW can use) and no OpenGL 3.3 there are the environment's
// lack, not the input's (ExitCode::NoDisplay).
GLFWwindow* openWindow(const sfbuild::SfbuildOptions& o, const tools::ToolOutput& output) {
  if (!glfwInit()) {
    std::string reason = glfwReason();
    output.error("no display to open a window on" + (reason.empty() ? "" : ": " + reason),
                 "run sfbuild in a graphical session, or under xvfb-run for scripts");
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, "sfbuild", nullptr, nullptr);
  if (!window) {
    std::string reason = glfwReason();
    output.error("cannot open an OpenGL 3.3 core window" + (reason.empty() ? "" : ": " + reason),
                 "the display's OpenGL is older than 3.3; Mesa's software OpenGL has 4.5");
    glfwTerminate();
  }
  return window;
}

}  // namespace

int main(int argc, char** argv) {
  tools::ToolStreams streams = tools::processStreams();
  sfbuild::SfbuildOptions options;
  std::unique_ptr<CLI::App> cli = sfbuild::makeSfbuildCommandLine(options);
  if (auto code = tools::parseCommandLine(*cli, argc, argv, streams.out, streams.err)) {
    return tools::closeStandardStreams("sfbuild", tools::toInt(*code));
  }
  tools::ToolOutput output("sfbuild", streams, options.common);

  App app;
  app.quiet = options.common.quiet;
  app.state = sfbuild::initialState(options.width, options.height);
  if (!options.input.empty()) {
    if (tools::MaybeFailure failure = openScene(options, output, app)) {
      return tools::closeStandardStreams("sfbuild", output.report(*failure));
    }
  }
  app.state.idView = options.idView;
  app.files.exists = [](const std::string& name) {
    std::error_code ec;
    return std::filesystem::exists(name, ec) || std::filesystem::is_symlink(name, ec);
  };
  app.files.write = [](const std::string& name, const std::string& content) {
    return tools::writeFileAtomically(name, content);
  };
  app.files.read = [](const std::string& name) { return tools::readWholeFile(name); };
  app.output = &output;

  GLFWwindow* window = openWindow(options, output);
  if (!window)
    return tools::closeStandardStreams("sfbuild", tools::toInt(tools::ExitCode::NoDisplay));
  glfwSetWindowUserPointer(window, &app);
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  glfwSetFramebufferSizeCallback(window, onFramebufferSize);
  glfwGetFramebufferSize(window, &app.state.width, &app.state.height);
  output.detail(std::string("OpenGL ") + reinterpret_cast<const char*>(glGetString(GL_VERSION)) +
                " on " + reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

  // The panels: ImGui's GLFW backend calls the callbacks above after its
  // own (it chains them); no imgui.ini, so every start looks the same.
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  app.state.showHelp = true;  // the key list, until H or F1 hides it

  int status = 0;
  try {
    sfbuild::GlView view;
    sfbuild::RayTracedView rayTracedView;
    RayTracing rayTracing;
    sfbuild::Panels panels;
    while (!glfwWindowShouldClose(window)) {
      handleKeys(app);
      if (app.state.rayTraced && !app.state.idView) {
        drawRayTraced(app, rayTracing, rayTracedView);
      } else {
        stopRayTracing(rayTracing, rayTracedView);
        view.draw(app.state);
      }
      // The id view is compared pixel by pixel with the renderer's ids: no
      // panels over it.
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      if (!app.state.idView) panels.draw(app.state, app.files);
      tellSave(app);
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
      std::string title = sfbuild::windowTitle(app.state);
      if (title != app.title) {
        glfwSetWindowTitle(window, title.c_str());
        app.title = title;
      }
      // A render under way hands over levels: look for them often.
      bool rendering = app.state.rayTraced && rayTracing.scene && !rayTracing.done;
      glfwWaitEventsTimeout(rendering ? 0.005 : 0.1);
    }
  } catch (const std::exception& e) {
    output.error(e.what());
    status = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return tools::closeStandardStreams("sfbuild", status);
}
