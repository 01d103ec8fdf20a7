#version 3.7;
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 80 right x*2 }
light_source { <4, 8, -6> color rgb 1 }
sphere { <0, 1, 0>, 1 pigment { color rgb <1, 0.3, 0.2> } }
box { <-3, -0.5, -3>, <3, 0, 3> pigment { color rgb <0.3, 0.6, 0.3> } }
