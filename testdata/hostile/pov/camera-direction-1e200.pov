camera { location 0 direction <1e200, 0, 1e200> }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 }
