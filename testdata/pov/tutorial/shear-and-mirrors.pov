/* A right-handed camera (right -x*4/3, as scenes exported from
   right-handed programs write it), a matrix with shear, non-uniform
   scale and a mirror. */
#include "colors.inc"

camera {
  location <4, 3, 7>
  look_at <0, 0.5, 0>
  right -x*4/3
  up y
}
light_source { <10, 12, 8> color White }

// x' = x + 0.6 y: the box leans.
box { <-0.5, 0, -0.5>, <0.5, 2, 0.5>
  matrix < 1,   0, 0,
           0.6, 1, 0,
           0,   0, 1,
          -2,   0, 0 >
  pigment { Orange }
}
sphere { 0, 1 scale <1.5, 0.4, 0.8> rotate <0, 0, 25> translate <1.5, 1, -1> pigment { Cyan } }
// A negative scale mirrors; the cylinder still stands where it should.
cylinder { <0, 0, 0>, <0, 1.5, 0>, 0.4 scale <-1, 1, 1> rotate x*-30 translate <0.5, 0, 2>
  pigment { Magenta } }
plane { y, 0 pigment { Gray70 } }
plane { z, -6 pigment { Gray30 } }
