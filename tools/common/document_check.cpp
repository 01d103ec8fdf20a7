#include "tools/common/document_check.h"

#include "tools/common/output_file_format.h"
#include "tools/common/output_location.h"

namespace tools {

DocumentCheck checkDocument(std::string_view text, const std::string& shownName,
                            const std::filesystem::path& folder,
                            const scene::ReadOptions& options) {
  DocumentCheck check{scene::detectFormat(text, shownName),
                      scene::parseScene(text, shownName, options)};
  if (check.format == scene::Format::InstructionFile) {
    scene::checkOutputLocation(check.result.scene, folder, scene::Severity::Warning,
                               check.result.diagnostics);
  }
  // Whatever the format: the OUTPUT_FILE a glTF, POV-Ray or OBJ file carries
  // becomes an instruction file's again when converted, and sfrender writes it.
  checkOutputFileFormat(check.result.scene, scene::Severity::Warning, check.result.diagnostics);
  return check;
}

}  // namespace tools
