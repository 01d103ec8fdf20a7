/// @file
/// sRGB's transfer curve (IEC 61966-2-1), the one rule for a display value's
/// linear light: the glTF reader and writer convert light colours with it,
/// and the renderer's float images store what it gives.
#pragma once

namespace scene {

/// Where the curve leaves its straight segment, in display terms. The
/// standard rounds the linear knee to 0.0031308; its exact image,
/// kSrgbDisplayKnee / 12.92, keeps the two functions each other's inverse at
/// the knee too.
inline constexpr double kSrgbDisplayKnee = 0.04045;
inline constexpr double kSrgbLinearKnee = kSrgbDisplayKnee / 12.92;

/// The linear value of a display value, carried on past 1 by the same
/// formula (a scene file's light colour may exceed 1); below 0 it is 0.
double srgbToLinear(double display);
/// The inverse: the display value of a linear one.
double linearToSrgb(double linear);

}  // namespace scene
