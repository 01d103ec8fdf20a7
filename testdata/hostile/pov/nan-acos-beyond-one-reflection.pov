camera { location <0, 1, -5> look_at <0, 0, 0> }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 finish { reflection acos(2) } }
