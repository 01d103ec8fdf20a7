camera { location <1e308, 1e308, 1e308> look_at <-1e308, -1e308, -1e308> }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 }
