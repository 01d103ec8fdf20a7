// Looking steeply down on a table, with sky to keep the picture upright.
#include "colors.inc"
camera {
  location <0.3, 9, -1.5>
  sky <0, 0, 1>
  look_at <0, 0, 0>
}
light_source { <3, 10, -4> color White }
plane { y, 0 pigment { color Wheat } }
box { <-2, 0, -1>, <2, 0.3, 1> pigment { SteelBlue } rotate y*30 }
sphere { <1.5, 0.7, 1.5>, 0.7 pigment { Firebrick } }
cylinder { <-2, 0, 1.5>, <-2, 1.2, 1.5>, 0.6 pigment { YellowGreen } }
