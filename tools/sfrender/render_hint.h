// Hints in sfrender's words: a remedy that sets a render's view to what
// this render uses already is left out. sfrender gives a POV-Ray or glTF
// camera's view itself, so "render with sfrender --fov 60" would tell its
// user to pass what they are getting.
#pragma once

#include <string>

#include "renderer/render.h"
#include "scenefile/diagnostic.h"

namespace tools {

// Whether `remedy` sets the field of view, width or height to what
// `settings` hold.
bool remedyInUse(const scene::Remedy& remedy, const render::RenderSettings& settings);

// d's hint in the tools' words (hintText) without the remedies in use;
// empty when every remedy the hint names is in use.
std::string renderHintText(const scene::Diagnostic& d, const render::RenderSettings& settings);

}  // namespace tools
