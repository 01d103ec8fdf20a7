// Standing under a canopy and looking up, with the camera given as
// vectors (no look_at): location, direction, up and right.
#include "colors.inc"
camera {
  location <0, 0.5, 0>
  direction <0, 1, 0.4>
  up <0, -0.4, 1>
  right <1.33, 0, 0>
}
light_source { <0, -5, 0> color White }
plane { y, 8 pigment { SkyBlue } }
sphere { <0, 6, 2>, 1.5 pigment { Coral } }
box { <-1, -1, -1>, <1, 1, 1> scale <2, 0.2, 1> rotate <0, 45, 0> translate <-3, 5, 3> pigment { Khaki } }
cylinder { <2, 4, 0>, <3, 7, 4>, 0.5 pigment { Orchid } }
