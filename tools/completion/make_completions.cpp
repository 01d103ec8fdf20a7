// Writes the bash completion of each tool into a folder, from the tools' own
// command lines (run at build time): make_completions FOLDER.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "scenefile/format.h"
#include "tools/common/output_file_format.h"
#include "tools/completion/bash_completion.h"
#include "tools/sfbuild/sfbuild_command_line.h"
#include "tools/sfcheck/sfcheck.h"
#include "tools/sfls/sfls_command_line.h"
#include "tools/sfconvert/sfconvert.h"
#include "tools/sfrender/sfrender.h"

namespace {

std::vector<std::string> withoutDots(std::vector<std::string_view> extensions) {
  std::vector<std::string> names;
  for (std::string_view e : extensions) names.emplace_back(e.substr(e.starts_with('.') ? 1 : 0));
  return names;
}

// Every extension of the format registry: what the tools read.
std::vector<std::string> sceneExtensions() {
  std::vector<std::string_view> all;
  for (const scene::FormatInfo& row : scene::formats()) {
    all.insert(all.end(), row.extensions.begin(), row.extensions.end());
  }
  return withoutDots(all);
}

std::vector<std::string> imageExtensions() {
  std::span<const std::string_view> list = tools::imageExtensions();
  return withoutDots({list.begin(), list.end()});
}

bool writeScript(const std::filesystem::path& folder, const CLI::App& app,
                 const tools::CompletedFiles& files) {
  std::ofstream out(folder / app.get_name());
  out << tools::bashCompletionScript(app, files);
  out.close();
  if (!out)
    std::cerr << "make_completions: error: cannot write " << (folder / app.get_name()) << "\n";
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "make_completions: error: name the folder to write the scripts in\n";
    return 2;
  }
  std::filesystem::path folder = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  tools::CompletedFiles scenes{sceneExtensions(), {}};
  tools::CompletedFiles render = scenes;
  render.options["--output"] = imageExtensions();

  tools::SfcheckOptions check;
  tools::SfconvertOptions convert;
  tools::SfrenderOptions renderOptions;
  sfbuild::SfbuildOptions build;
  sfls::SflsOptions server;
  bool ok = writeScript(folder, *tools::makeSfcheckCommandLine(check), scenes) &&
            writeScript(folder, *tools::makeSfconvertCommandLine(convert), scenes) &&
            writeScript(folder, *tools::makeSfrenderCommandLine(renderOptions), render) &&
            writeScript(folder, *sfbuild::makeSfbuildCommandLine(build), scenes) &&
            writeScript(folder, *sfls::makeSflsCommandLine(server), tools::CompletedFiles{});
  return ok ? 0 : 3;
}
