// The package's files written by the tools' own file code
// (tools/common/file_io.h), so that a script's write keeps every promise a
// tool's does (docs/SECURITY.md, "What each tool writes"): a folder, a
// device or a pipe refused, links followed and kept, the permissions of a
// replaced file kept, a set of files written whole or not at all.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <utility>

namespace scenefile_python {

namespace py = pybind11;

// write_files([(path, data)]): the files, as bytes paths (os.fsencode) and
// their bytes, written together in the order given. None when all are
// written; else (path, reason) of the one that could not be, and none is.
std::optional<std::pair<py::bytes, std::string>> writeFiles(const py::list& files);

// output_clash(inputs, outputs): the tools' check that no output is an
// input and no two outputs are one file, by file identity
// (tools/common/output_plan.h). `inputs` are bytes paths, `outputs` (bytes
// path, the input it is made from, its role: "" or "its buffer"). None, or
// the first clash in the tools' words.
std::optional<std::string> outputClash(const py::list& inputs, const py::list& outputs);

}  // namespace scenefile_python
