/// @file
/// What writing an instruction file can be told beyond the common options.
#pragma once

#include <string>

namespace scene {

/// Options of the instruction file writer.
struct InstructionWriteOptions {
  /// Write the nearest expressible form of a matrix with shear or of a rolled
  /// camera, and report how far each value moved, instead of failing
  /// (Setting::Approximate). Under ConversionOptions::noLoss an
  /// approximation is still an error.
  bool approximate = false;
  /// OUTPUT_FILE for a scene that has none (one read from a scene file).
  std::string outputFile = "output.ppm";

  friend bool operator==(const InstructionWriteOptions&, const InstructionWriteOptions&) = default;
};

}  // namespace scene
