camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 pigment { bozo colour_map { [1e308 * 10 rgb 1] } } }
