// checkSceneFinite in its two parts, so that a reader of a big scene can
// test its objects on several threads (libscene/read.cpp).
#pragma once

#include <span>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scene {

/// checkSceneFinite for the camera, its view and the lights.
bool checkFramingFinite(const Scene& scene, DiagnosticList& out);
/// checkSceneFinite for a scene's objects.
bool checkObjectsFinite(std::span<const Object> objects, DiagnosticList& out);
/// Whether every number of `object` is finite: checkObjectsFinite's test,
/// without its report.
bool objectFinite(const Object& object);
/// Whether every object of `objects` is finite, the test shared out to up
/// to `threads` threads (0: every core) where there are enough objects for
/// that to pay; false also where a thread could not start.
bool objectsFinite(std::span<const Object> objects, unsigned threads);

}  // namespace scene
