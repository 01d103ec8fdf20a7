#include "python/src/render_image.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <vector>

#include "renderer/render_memory.h"
#include "renderer/render_settings.h"

namespace scenefile_python {

namespace {

// How often the waiting thread lets Python look at its signals: Ctrl+C
// stops a render within this and one row of pixels.
constexpr std::chrono::milliseconds kSignalPoll{50};

// The image's floats, handed to numpy without a copy: the array owns them.
py::array_t<float> toArray(scene::RenderedImage&& image) {
  auto* rgb = new std::vector<float>(std::move(image.rgb));
  py::capsule owner(rgb, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  std::vector<py::ssize_t> shape = {image.height, image.width, 3};
  return py::array_t<float>(shape, rgb->data(), owner);
}

// Runs `work` on a thread of its own and waits for it without the GIL,
// taking the GIL every kSignalPoll to run Python's signal handlers; when one
// raises, a stop is requested of `stop` and, once `work` is done, the
// exception goes on.
template <typename Work>
void runInterruptibly(Work&& work, std::stop_source& stop) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      work();
      std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, kSignalPoll, [&] { return done; })) {
      if (interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        // Only the main thread runs handlers; elsewhere this returns 0.
        if (PyErr_CheckSignals() != 0) interrupted = true;
      }
      if (interrupted) stop.request_stop();
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  // The handler's exception is still set on this thread: raise it.
  if (interrupted) throw py::error_already_set();
}

}  // namespace

py::array_t<float> renderToArray(const scene::Scene& scene, const scene::RenderSettings& settings) {
  // As scene::renderScene renders it: the settings as the renderer's, so
  // that the lights' grids are counted only where it builds them.
  render::RenderSettings full;
  static_cast<scene::RenderSettings&>(full) = settings;
  render::RenderMemoryEstimate estimate =
      render::estimateRenderMemory(render::renderSizeOf(scene, full));
  if (std::optional<std::string> refusal =
          render::renderMemoryRefusal(estimate, render::readAvailableMemory())) {
    PyErr_SetString(PyExc_MemoryError, refusal->c_str());
    throw py::error_already_set();
  }
  std::stop_source stop;
  std::optional<scene::RenderedImage> image;
  std::exception_ptr failure;
  runInterruptibly(
      [&] {
        try {
          image = scene::renderScene(scene, settings, {{}, stop.get_token()});
        } catch (...) {
          failure = std::current_exception();
        }
      },
      stop);
  // std::bad_alloc becomes MemoryError, std::system_error (threads that
  // cannot start) RuntimeError.
  if (failure) std::rethrow_exception(failure);
  return toArray(std::move(*image));
}

}  // namespace scenefile_python
