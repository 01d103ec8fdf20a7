// "Simple shapes" in the manner of POV-Ray's tutorial: a box, a cone-less
// set of primitives, named colours and rotations in degrees.
#version 3.7;
#include "colors.inc"
#include "textures.inc"

camera {
  location <0, 2, -4>
  look_at  <0, 1,  2>
}

light_source { <2, 4, -3> color White }
light_source { <-4, 6, -2> color Gray50 }

box {
  <-1,   0,   -1>,  // Near lower left corner
  < 1,   0.5,  3>   // Far upper right corner
  texture {
    pigment { color Red }
  }
  rotate y*20       // Equivalent to "rotate <0,20,0>"
}

cylinder {
  <0, 1, 0>,     // Center of one end
  <1, 2, 3>,     // Center of other end
  0.5            // Radius
  pigment { color Blue }
}

sphere { <-2.2, 0.6, 1.5>, 0.6 pigment { color ForestGreen } finish { phong 1 } }

plane { <0, 1, 0>, -1
  pigment { color rgb <0.7, 0.7, 0.75> }
}
