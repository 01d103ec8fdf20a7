// The module's check(): sfcheck's diagnostics of one text.
#pragma once

#include <string>
#include <string_view>

namespace web {

// {"format": the registry's --to name of the format recognised, or null,
// "diagnostics": exactly the diagnostics of sfcheck --format json's entry
// for a file of this text named `name`}.
std::string checkJson(std::string_view text, const std::string& name);

// The registry's rows as a JSON array of {name, description, extensions,
// reads, writes, binary}.
std::string formatsJson();

}  // namespace web
