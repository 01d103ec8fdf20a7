// Rendering for Python: the renderer on a thread of its own while the
// caller's thread, without the GIL, waits and now and then takes the GIL
// back for a moment to let Python run its signal handlers, so that Ctrl+C
// stops the render (a stop request, scenefile/render.h) and raises
// KeyboardInterrupt.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "scenefile/render.h"
#include "scenefile/scene.h"

namespace scenefile_python {

namespace py = pybind11;

// The image scene::renderScene computes, as a float32 array of shape (height,
// width, 3), rows from the top: the numbers sfrender writes. MemoryError
// when the render would not fit in the memory that is free; whatever a
// signal handler raises (KeyboardInterrupt) when one interrupts it.
py::array_t<float> renderToArray(const scene::Scene& scene, const scene::RenderSettings& settings);

}  // namespace scenefile_python
