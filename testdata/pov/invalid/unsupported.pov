// Constructs outside the subset, each named with its line.
#include "colors.inc"
camera { location <0, 1, -5> look_at 0 }
light_source { <0, 5, -5> color White }
union {
  sphere { 0, 1 }
  box { 0, 1 }
}
difference { box { -1, 1 } sphere { 0, 1.2 } }
torus { 1, 0.25 pigment { Red } }
#declare I = 0;
#while (I < 10)
  sphere { <I, 0, 0>, 0.2 }
  #declare I = I + 1;
#end
#macro Ball(P) sphere { P, 1 } #end
Ball(<1, 2, 3>)
sphere { 0, 1 pigment { checker Red White } normal { bumps 0.4 } }
sky_sphere { pigment { gradient y color_map { [0 White] [1 Blue] } } }
camera { orthographic location <0, 0, -5> look_at 0 }
box { -1, 1 pigment { Green } }
