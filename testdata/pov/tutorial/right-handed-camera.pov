/* A right-handed camera, as glTF and OpenGL users set POV-Ray up:
   right -x*image_width/image_height. */
#include "colors.inc"
camera {
  location <3, 4, -6>
  look_at <0, 0.5, 0>
  right -x*image_width/image_height
  angle 50
}
light_source { <5, 10, -5> White }
#declare Radius = 0.75;
#declare Lift = <0, Radius, 0>;
sphere { Lift, Radius pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.6 phong_size 80 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { color ForestGreen } rotate y*30 translate <1.8, 0, 0.5> }
cylinder { <-2, 0, 0>, <-2, 1.5, 0.5>, 0.4 pigment { color SkyBlue } }
plane { y, 0 pigment { color Gray50 } }
// A shear: x' = x + 0.5 y.
box { -0.25, 0.25 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0.25, -1.5> pigment { Orange } }
