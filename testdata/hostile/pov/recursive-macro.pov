camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#macro Boom(N)
  sphere { 0, 1 }
  Boom(N + 1)
#end
Boom(0)
