camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 pigment { marble colour_map { [0 rgb -1.7e308] [1 rgb -1.7e308] } } }
