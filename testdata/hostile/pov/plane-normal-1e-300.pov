camera { location <0, 1, -5> look_at <0, 0, 0> }
light_source { <5, 5, -5> color rgb 1 }
plane { <0, 1e-300, 0>, 0 }
