# The CPU renderer's sources, for this folder's CMakeLists.txt and the web
# build's (web/wasm/); the GPU path's are added by this folder alone.
set(renderer_cpu_sources)
foreach(name bvh bvh_morton bvh_node direction_grid adaptive_sampling anchor_blocks camera camera_trace cpu_render default_scene device image
        material_maxima radiance_bound render render_memory render_scene render_scene_builder render_settings sample_sequence tracer
        scene_render unit_shapes)
  list(APPEND renderer_cpu_sources ${CMAKE_CURRENT_LIST_DIR}/${name}.cpp)
endforeach()
