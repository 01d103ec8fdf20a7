// Each statement with a mistake is reported, and reading goes on.
camera { location <0, 1, -5> look_at 0 }
sphere { 0, 1 pigment { rgb <1, 0> } }
box { -1, 1 transalte x }
cylinder { 0, y, 1 pigment { color rgb 1 } finish { phong_sise 20 } }
sphre { 0, 1 }
sphere { <1, 2, 3> 0.5 translate <1, 2 }
}
light_source { <0, 5, -5> color rgb 1 }
plane { y, -1 }
/* never closed
