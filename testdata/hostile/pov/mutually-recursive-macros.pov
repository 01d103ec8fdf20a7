camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#macro Ping(N)
  Pong(N)
#end
#macro Pong(N)
  Ping(N)
#end
Ping(0)
