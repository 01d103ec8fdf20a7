// Writes seeded random scenes as scene files, for the tests that run other
// programs on what sfconvert makes of them (the glTF Validator).
// Usage: make_random_scenes FOLDER COUNT SEED [moderate]
// `moderate` keeps every number within 1e6 (no 1e300, no subnormals): what
// a program that reads glTF in single precision can hold.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "libscene/testing/random_scenes.h"
#include "scenefile/read.h"
#include "libscene/formats/sf/sf_writer.h"

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::cerr << "usage: make_random_scenes FOLDER COUNT SEED [moderate]\n";
    return 2;
  }
  std::filesystem::path folder = argv[1];
  int count = std::atoi(argv[2]);
  scene::testing::RandomSceneGenerator random(std::strtoull(argv[3], nullptr, 10));
  bool extreme = argc != 5 || std::string(argv[4]) != "moderate";
  std::filesystem::create_directories(folder);
  for (int written = 0; written < count;) {
    std::string text = scene::writeSceneFile(random.scene(extreme));
    if (!scene::parseScene(text, "random.sf").ok()) continue;
    std::ofstream(folder / ("random-" + std::to_string(written++) + ".sf"), std::ios::binary)
        << text;
  }
  return 0;
}
