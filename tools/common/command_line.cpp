#include "tools/common/command_line.h"

namespace tools {

std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, const char* const* argv,
                                         std::ostream& out, std::ostream& err) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return ExitCode::Success;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return ExitCode::Success;
  } catch (const CLI::CallForVersion&) {
    out << app.version() << "\n";
    return ExitCode::Success;
  } catch (const CLI::ParseError& e) {
    err << app.get_name() << ": " << e.what() << "\n";
    err << "run '" << app.get_name() << " --help' for the options\n";
    return ExitCode::Usage;
  }
  return std::nullopt;
}

}  // namespace tools
