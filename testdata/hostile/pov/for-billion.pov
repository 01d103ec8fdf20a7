camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#for (I, 0, 1e9)
  sphere { <I, 0, 0>, 0.5 }
#end
