// count-objects FILE: reads a scene in any format the library knows (.sf,
// instruction file, glTF, POV-Ray) and prints "N objects, M lights". A file
// that cannot be read as a scene gets its diagnostics on standard error in
// the short form (FILE:LINE:COLUMN: SEVERITY: MESSAGE [code]), and exit 1.
// Exit 2 is a usage error, 3 a file that cannot be read.
#include <scenefile/diagnostic_format.h>
#include <scenefile/read_file.h>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]).empty() || argv[1][0] == '-') {
    std::cerr << "usage: count-objects FILE\n";
    return 2;
  }
  scene::ReadResult result = scene::readSceneFile(argv[1]);
  scene::DiagnosticFormOptions form;
  form.form = scene::DiagnosticForm::Short;
  std::cerr << scene::formatDiagnostics(result.diagnostics, form);
  for (const scene::Diagnostic& d : result.diagnostics.items()) {
    if (d.code == scene::DiagnosticCode::CannotReadFile) return 3;
  }
  if (!result.ok()) return 1;
  std::cout << result.scene.objects.size() << " objects, " << result.scene.lights.size()
            << " lights\n";
  return 0;
}
