camera { location <0, 1, -5> look_at <0, 0, 0> }
light_source { <0/0, 10, -10> color rgb <1, 1, 1> }
sphere { 0, 1 }
