#include "python/src/file_writes.h"

#include <filesystem>
#include <vector>

#include "tools/common/file_io.h"
#include "tools/common/output_plan.h"

namespace scenefile_python {

std::optional<std::pair<py::bytes, std::string>> writeFiles(const py::list& files) {
  // The bytes objects stay referenced by `files` while the GIL is released,
  // and bytes never change: the views stay valid.
  std::vector<tools::FileToWrite> toWrite;
  for (py::handle item : files) {
    auto pair = py::cast<py::tuple>(item);
    auto path = py::cast<std::string>(pair[0]);
    py::bytes data = pair[1];
    char* buffer = nullptr;
    py::ssize_t size = 0;
    PyBytes_AsStringAndSize(data.ptr(), &buffer, &size);
    toWrite.push_back({std::filesystem::path(path), {buffer, static_cast<std::size_t>(size)}});
  }
  tools::MaybeFailure failure;
  {
    py::gil_scoped_release release;
    failure = tools::writeFilesAtomically(toWrite);
  }
  if (!failure) return std::nullopt;
  return std::make_pair(py::bytes(failure->file), failure->message);
}

std::optional<std::string> outputClash(const py::list& inputs, const py::list& outputs) {
  tools::OutputPlan plan;
  for (py::handle input : inputs) plan.addInput(py::cast<std::string>(input));
  for (py::handle item : outputs) {
    auto output = py::cast<py::tuple>(item);
    plan.addOutput(py::cast<std::string>(output[0]), py::cast<std::string>(output[1]),
                   py::cast<std::string>(output[2]));
  }
  std::optional<tools::OutputClash> clash = plan.firstClash();
  if (!clash) return std::nullopt;
  return plan.describe(*clash);
}

}  // namespace scenefile_python
