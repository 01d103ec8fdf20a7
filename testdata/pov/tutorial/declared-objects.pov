// #declare of numbers, vectors, colours, finishes and objects, and
// `object { }` to place them, as POV-Ray users lay out a scene.
#version 3.7;
#include "colors.inc"

#declare Spacing = 1.5;
#declare Lift = 0.5 * y;
#declare Shiny = finish { phong 0.9 phong_size 60 reflection 0.1 }
#declare Post = cylinder { 0, 2 * y, 0.2 finish { Shiny } }
#declare Ball = sphere { Lift, 0.5 texture { pigment { color rgb <1, 0.8, 0.2> } finish { Shiny } } }

camera {
  location <1, 3.5, -7>
  look_at <1, 0.5, 0>
  angle 55
}
light_source { <-5, 10, -10> color White }

object { Post translate -Spacing * x pigment { Red } }
object { Post pigment { Green } rotate z * 15 }
object { Post translate Spacing * x pigment { Blue } rotate <10, 0, -10> }
object { Ball translate <-Spacing, 2, 0> }
object { Ball translate <Spacing * 2, 0, 1> scale <1, 1.5, 1> }
box { <-3, -0.1, -2>, <5, 0, 3> pigment { color Tan } }
