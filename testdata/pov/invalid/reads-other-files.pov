// A scene that would make POV-Ray read other files is refused.
#include "colors.inc"
#include "my_textures.inc"
camera { location <0, 1, -5> look_at 0 }
#fopen Data "points.txt" read
sphere { 0, 1 pigment { image_map { png "earth.png" } } }
height_field { png "terrain.png" }
