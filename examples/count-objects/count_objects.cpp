// count-objects FILE: reads a scene in any format the library knows (.sf,
// instruction file, glTF, POV-Ray) and prints "N objects, M lights". A file
// that cannot be read as a scene gets its diagnostics, one per line as
// FILE:LINE:COLUMN: SEVERITY: MESSAGE, on standard error, and exit 1.
// Exit 2 is a usage error, 3 a file that cannot be read.
#include <scenefile/read.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

namespace {

void printAt(const std::string& file, const scene::SourceSpan& span, scene::Severity severity,
             const std::string& message) {
  std::cerr << file << ':';
  if (span.known()) std::cerr << span.line << ':' << span.column << ':';
  std::cerr << ' ' << scene::severityName(severity) << ": " << message << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]).empty() || argv[1][0] == '-') {
    std::cerr << "usage: count-objects FILE\n";
    return 2;
  }
  std::string path = argv[1];
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << path << ": error: cannot open the file\n";
    return 3;
  }
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};

  scene::ReadResult result = scene::parseScene(text, path);
  for (const scene::Diagnostic& d : result.diagnostics.items()) {
    const std::string& file = d.file.empty() ? path : d.file;
    printAt(file, d.span, d.severity, d.message);
    for (const scene::DiagnosticNote& note : d.notes) {
      printAt(file, note.span, scene::Severity::Note, note.message);
    }
  }
  if (!result.ok()) return 1;
  std::cout << result.scene.objects.size() << " objects, " << result.scene.lights.size()
            << " lights\n";
  return 0;
}
