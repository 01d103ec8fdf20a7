// Shapes with no extent.
camera { location <0, 1, -5> look_at 0 }
light_source { <0, 5, -5> color rgb 1 }
sphere { <1, 2, 3>, 0 }
box { <0, 0, 0>, <1, 0, 1> }
cylinder { <1, 1, 1>, <1, 1, 1>, 0.5 }
plane { <0, 0, 0>, 1 }
sphere { 0, 1 scale <1, 1e-20, 1> }
