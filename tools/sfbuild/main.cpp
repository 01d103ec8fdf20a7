// sfbuild: the interactive scene builder. GLFW's callbacks become calls on
// the BuilderState; GlView draws it.
#include <epoxy/gl.h>
// GLFW after the loader, which brings the GL declarations.
#include <GLFW/glfw3.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "scenefile/read.h"
#include "tools/common/command_line.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/file_io.h"
#include "tools/common/input_limits.h"
#include "tools/sfbuild/builder_state.h"
#include "tools/sfbuild/gl_view.h"

namespace {

struct App {
  sfbuild::BuilderState state;
  sfbuild::FileSystem files;
  std::string title;
};

App* appOf(GLFWwindow* window) {
  return static_cast<App*>(glfwGetWindowUserPointer(window));
}

int builderKey(int key) {
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) {
    return key;  // GLFW's codes for these are their ASCII characters
  }
  if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) return '0' + (key - GLFW_KEY_KP_0);
  switch (key) {
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

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && !(action == GLFW_REPEAT && key == GLFW_KEY_BACKSPACE)) return;
  int k = builderKey(key);
  if (k < 0) return;
  App& app = *appOf(window);
  bool helpBefore = app.state.showHelp;
  sfbuild::handleKey(app.state, k, app.files);
  if (app.state.showHelp && !helpBefore) {
    for (const std::string& line : sfbuild::helpLines()) std::cout << line << "\n";
    std::cout.flush();
  }
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
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
  sfbuild::handleScroll(appOf(window)->state, dy);
}

void onFramebufferSize(GLFWwindow* window, int width, int height) {
  if (width <= 0 || height <= 0) return;
  appOf(window)->state.width = width;
  appOf(window)->state.height = height;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"The interactive scene builder: P saves Scene<n>.sf in the current folder",
               "sfbuild"};
  cli.set_version_flag("--version", SCENEFILE_VERSION);
  std::string input;
  int width = 640, height = 480;
  bool idView = false;
  cli.add_option("scene", input, "a scene to open (any format sfrender reads)");
  cli.add_option("--width", width, "window width in pixels")->check(CLI::Range(64, 8192));
  cli.add_option("--height", height, "window height in pixels")->check(CLI::Range(64, 8192));
  cli.add_flag("--id-view", idView, "draw each object in a flat colour of its own (F9 toggles)");
  scene::ReadOptions readOptions;
  tools::addReadLimitOptions(cli, readOptions);
  if (auto code = tools::parseCommandLine(cli, argc, argv, std::cout, std::cerr)) {
    return tools::toInt(*code);
  }

  App app;
  app.state = sfbuild::initialState(width, height);
  if (!input.empty()) {
    tools::InputText text = tools::readInputText(input, readOptions);
    if (text.tooLarge()) {
      tools::printDiagnostics(text.refused, std::cerr);
      return tools::toInt(tools::ExitCode::InvalidInput);
    }
    if (!text.text) {
      std::cerr << "sfbuild: " << text.readError << "\n";
      return tools::toInt(tools::ExitCode::IoError);
    }
    scene::ReadResult result = scene::parseScene(*text.text, input, readOptions);
    tools::printDiagnostics(result.diagnostics, std::cerr);
    if (!result.ok()) return tools::toInt(tools::ExitCode::InvalidInput);
    app.state = sfbuild::stateForScene(std::move(result.scene), width, height);
  }
  app.state.idView = idView;
  app.files.exists = [](const std::string& name) {
    std::error_code ec;
    return std::filesystem::exists(name, ec) || std::filesystem::is_symlink(name, ec);
  };
  app.files.write = [](const std::string& name, const std::string& content, std::string& error) {
    return tools::writeFileAtomically(name, content, error);
  };

  if (!glfwInit()) {
    std::cerr << "sfbuild: cannot start GLFW (is there a display?)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window = glfwCreateWindow(width, height, "sfbuild", nullptr, nullptr);
  if (!window) {
    std::cerr << "sfbuild: cannot open an OpenGL 3.3 core window\n";
    glfwTerminate();
    return 1;
  }
  glfwSetWindowUserPointer(window, &app);
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  glfwSetFramebufferSizeCallback(window, onFramebufferSize);
  glfwGetFramebufferSize(window, &app.state.width, &app.state.height);

  int status = 0;
  try {
    sfbuild::GlView view;
    while (!glfwWindowShouldClose(window)) {
      view.draw(app.state);
      glfwSwapBuffers(window);
      std::string title = sfbuild::windowTitle(app.state);
      if (title != app.title) {
        glfwSetWindowTitle(window, title.c_str());
        app.title = title;
      }
      glfwWaitEventsTimeout(0.1);
    }
  } catch (const std::exception& e) {
    std::cerr << "sfbuild: " << e.what() << "\n";
    status = 1;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
