// Writes the scene that sfrender draws with no input as an instruction file
// (materials included), so that sfconvert can export it: sfconvert reads
// files only. Usage: write_default_scene OUT.txt
#include <filesystem>
#include <fstream>
#include <iostream>

#include "renderer/default_scene.h"
#include "scenefile/convert.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_default_scene OUT.txt\n";
    return 2;
  }
  scene::DiagnosticList diagnostics;
  scene::ConversionOptions options;
  options.instructions.approximate = true;
  std::optional<std::string> text = scene::convertScene(
      render::defaultScene(), scene::Format::InstructionFile, options, diagnostics);
  if (!text) {
    std::cerr
        << "write_default_scene: the default scene cannot be written as an instruction file\n";
    return 1;
  }
  std::filesystem::path path = argv[1];
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << *text;
  return out ? 0 : 1;
}
