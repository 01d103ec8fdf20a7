// The first scene of POV-Ray's tutorial, as its users write it.
#version 3.7;
#include "colors.inc"    // the named colours
global_settings { assumed_gamma 1.0 }
background { color Black }
camera {
  location <0, 2, -3>
  look_at  <0, 1,  2>
}
sphere {
  <0, 1, 2>, 2
  texture {
    pigment { color Yellow }
  }
}
light_source { <2, 4, -3> color White }
