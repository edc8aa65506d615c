# The unit, property and editor tests (GoogleTest) and the command-line checks: included by
# tests/CMakeLists.txt unless GLINT_UNIT_TESTS is off. The test command runs them in its sanitizer
# build; its optimised build leaves them out (third_party/bootstrap.sh), so each runs once.

# Core: pure C++, no GL context.
add_executable(core_tests
  brdf_file_test.cpp
  brdf_test.cpp
  classroom_display_test.cpp
  environment_test.cpp
  fresnel_test.cpp
  interchange_gltf_test.cpp
  interchange_glb_test.cpp
  interchange_merl_test.cpp
  measured_material_test.cpp
  interchange_mtl_test.cpp
  asset_test.cpp
  light_test.cpp
  mesh_import_test.cpp
  mesh_normals_test.cpp
  scene_shapes_test.cpp
  specular_transport_test.cpp
  geometry_camera_test.cpp
  openpbr_test.cpp
  presets_test.cpp
  reference_renderer_test.cpp
  scene_json_test.cpp
  scene_json_lights_test.cpp
  scene_json_shadows_test.cpp
  shader_sources_test.cpp
  texture_test.cpp)
target_sources(core_tests PRIVATE classroom_lessons_test.cpp colour_test.cpp)  # classroom: lessons, CIE colour
# Metal spectra and the presets' per-channel indices fitted to them (issue 3): the program holds
# the presets' numbers (core/brdf/presets.cpp), the tests compute them again from the spectra.
target_sources(core_tests PRIVATE metal_spectra_test.cpp metal_index_fit.cpp metal_spectra.cpp reflectance_colour.cpp)
target_sources(core_tests PRIVATE mesh_simplify_test.cpp mesh_topology_test.cpp)  # large meshes: stand-ins, culling
target_sources(core_tests PRIVATE wild_files_test.cpp)  # files other tools wrote (tests/files/README.md)
target_sources(core_tests PRIVATE model_machinery_test.cpp)  # the model machinery on a test-only model; docs/models.md
target_sources(core_tests PRIVATE model_traits_test.cpp)  # what models declare they do; no model ids compared outside core/brdf
target_sources(core_tests PRIVATE interchange_gltf_openpbr_test.cpp)  # glTF materials ↔ openpbr
target_sources(core_tests PRIVATE interchange_gltf_images_test.cpp)  # images inside .glb and .gltf files
target_sources(core_tests PRIVATE disk_cache_test.cpp)  # the disk cache of computed tables
target_sources(core_tests PRIVATE reference_confinement_test.cpp)  # files that files name: confined to their folder
target_sources(core_tests PRIVATE interchange_materialx_test.cpp model_switch_test.cpp)  # MaterialX; switching models
target_sources(core_tests PRIVATE material_change_test.cpp)  # the pixels a material change reaches
target_sources(core_tests PRIVATE frame_plan_test.cpp)  # what a renderer frame draws, decided without GL
target_compile_definitions(core_tests PRIVATE ${GLINT_TEST_DEFINITIONS})
target_link_libraries(core_tests PRIVATE glint_gl GTest::gtest_main)
glint_add_gtests(core_tests SHARDS 6 ENVIRONMENT GLINT_CACHE_DIR=${CMAKE_CURRENT_BINARY_DIR}/output/cache)

# The app's pieces that need no GL context: editing state (undo, autosave), snapshot suites and
# reports, the classroom's compare layouts, plot data and probe text.
add_executable(app_tests classroom_compare_test.cpp classroom_plot_data_test.cpp edit_session_test.cpp snapshot_suite_test.cpp
  surface_probe_test.cpp recovery_lock_test.cpp)
target_compile_definitions(app_tests PRIVATE ${GLINT_TEST_DEFINITIONS})
target_link_libraries(app_tests PRIVATE glint_app_lib GTest::gtest_main)
glint_add_gtests(app_tests SHARDS 2)

# An outside importer (assimp, libassimp-dev) opens Glint's exported glTF.
find_package(assimp CONFIG REQUIRED)
add_executable(gltf_assimp_tests gltf_assimp_test.cpp)
target_compile_definitions(gltf_assimp_tests PRIVATE ${GLINT_TEST_DEFINITIONS})
target_link_libraries(gltf_assimp_tests PRIVATE glint_core assimp::assimp GTest::gtest_main)
glint_add_gtests(gltf_assimp_tests SHARDS 1)

# The editor's document actions (open, drop, save, autosave) without a window.
add_executable(editor_tests editor_compare_test.cpp editor_document_test.cpp editor_objects_test.cpp editor_interchange_test.cpp
  editor_brdf_test.cpp editor_environment_test.cpp)
target_sources(editor_tests PRIVATE editor_refresh_test.cpp)  # reduced frames while dragging, then the full one
target_sources(editor_tests PRIVATE viewport_presenter_test.cpp)  # the rectangles redrawn and what each shows
# Classroom: lessons and presentation mode; the CIE plot drawn headless (its own OSMesa context).
target_sources(editor_tests PRIVATE editor_classroom_test.cpp cmf_plot_headless_test.cpp)
target_sources(editor_tests PRIVATE editor_window_placement_test.cpp)  # where floating windows open
target_compile_definitions(editor_tests PRIVATE ${GLINT_TEST_DEFINITIONS} GLINT_EXECUTABLE="$<TARGET_FILE:glint>")
add_dependencies(editor_tests glint)  # the .brdf probe runs `glint probe-brdf`
target_link_libraries(editor_tests PRIVATE glint_app_lib GTest::gtest_main)
glint_add_gtests(editor_tests SHARDS 2 ENVIRONMENT DISPLAY=)

# The manual: every relative link in README.md and docs/*.md resolves.
add_test(NAME doc_links COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/doc_links_test.py ${PROJECT_SOURCE_DIR})

# Commit messages: the repository's hook judges the subject's length and the blank line.
add_test(NAME commit_msg_hook COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/commit_msg_hook_test.sh ${PROJECT_SOURCE_DIR})

# Layering: core must not include GL, GLFW or ImGui headers.
add_test(NAME core_has_no_gl_includes
  COMMAND ${CMAKE_COMMAND} -DCORE_DIR=${PROJECT_SOURCE_DIR}/core -P ${CMAKE_CURRENT_SOURCE_DIR}/check_core_layering.cmake)

# The CLI on bad input: exit code 2 and a located message, never a crash.
add_test(NAME cli_bad_input COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_test.sh $<TARGET_FILE:glint> ${CMAKE_CURRENT_BINARY_DIR}/output/cli)
set_tests_properties(cli_bad_input PROPERTIES ENVIRONMENT "DISPLAY=")
# The classroom surface probe through `glint render --probe X,Y --overlay probe`.
add_test(NAME probe_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/probe_cli_test.sh $<TARGET_FILE:glint> ${CMAKE_CURRENT_BINARY_DIR}/output/probe_cli)
set_tests_properties(probe_cli PROPERTIES ENVIRONMENT "DISPLAY=")
# .mtl and .gltf through `glint export` and `glint render`: round trips, renders, located errors.
add_test(NAME interchange_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/interchange_cli_test.sh $<TARGET_FILE:glint> ${CMAKE_CURRENT_BINARY_DIR}/output/interchange_cli)
set_tests_properties(interchange_cli PROPERTIES ENVIRONMENT "DISPLAY=" TIMEOUT 480)
# Files naming files outside their folder, in every format that names files: refused by name,
# read with --allow-outside-references, never quoted (tests/files/hostile/).
add_test(NAME hostile_references COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hostile_references_test.sh $<TARGET_FILE:glint>
         ${CMAKE_CURRENT_BINARY_DIR}/output/hostile_references)
set_tests_properties(hostile_references PROPERTIES ENVIRONMENT "DISPLAY=" TIMEOUT 300)

# Classroom plots through `glint render --overlay polar|lobe|albedo|fresnel`: PNGs and bad options.
add_test(NAME plots_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/plots_cli_test.sh $<TARGET_FILE:glint>
         ${CMAKE_CURRENT_BINARY_DIR}/output/plots_cli ${CMAKE_CURRENT_SOURCE_DIR})
set_tests_properties(plots_cli PROPERTIES ENVIRONMENT "DISPLAY=" TIMEOUT 120)

# The path tracer (core/render/path_tracer.h): Monte-Carlo, in a binary of its own so that it
# builds and runs apart from the larger core suite.
add_executable(path_tracer_tests path_tracer_test.cpp)
target_compile_definitions(path_tracer_tests PRIVATE ${GLINT_TEST_DEFINITIONS})
target_link_libraries(path_tracer_tests PRIVATE glint_core GTest::gtest_main)
glint_add_gtests(path_tracer_tests SHARDS 1 ENVIRONMENT GLINT_CACHE_DIR=${CMAKE_CURRENT_BINARY_DIR}/output/cache)
# `glint render --path-trace`: its refusals, progress and determinism.
add_test(NAME path_trace_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/path_trace_cli_test.sh $<TARGET_FILE:glint>
         ${CMAKE_CURRENT_BINARY_DIR}/output/path_trace_cli)
set_tests_properties(path_trace_cli PROPERTIES ENVIRONMENT "DISPLAY=" TIMEOUT 120)
