# glint_add_snapshot_test(NAME DIR [OUT DIR] [JOBS N] [SHARD I/N] [GLINT PATH] [ARGS ...]):
# registers `glint snapshot DIR` with ctest, for Glint's own goldens and for any project that
# include()s this file. It finds glint as: GLINT PATH, else the GLINT_EXECUTABLE variable, else
# the `glint` target of the same build, else `glint` on PATH. It does not build or install glint.
include_guard(GLOBAL)

function(glint_add_snapshot_test name dir)
  cmake_parse_arguments(PARSE_ARGV 2 snapshot "" "OUT;JOBS;SHARD;GLINT" "ARGS")
  if(snapshot_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "glint_add_snapshot_test(${name}): unknown arguments ${snapshot_UNPARSED_ARGUMENTS} "
                        "(expected OUT, JOBS, SHARD, GLINT, ARGS)")
  endif()

  if(snapshot_GLINT)
    set(glint "${snapshot_GLINT}")
  elseif(GLINT_EXECUTABLE)
    set(glint "${GLINT_EXECUTABLE}")
  elseif(TARGET glint)
    set(glint "$<TARGET_FILE:glint>")
  else()
    find_program(GLINT_EXECUTABLE glint DOC "the glint executable that renders snapshot suites")
    if(NOT GLINT_EXECUTABLE)
      message(FATAL_ERROR "glint_add_snapshot_test(${name}): glint not found; set GLINT_EXECUTABLE to its path "
                          "(e.g. cmake -DGLINT_EXECUTABLE=/path/to/glint)")
    endif()
    set(glint "${GLINT_EXECUTABLE}")
  endif()

  get_filename_component(suite "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT snapshot_OUT)
    set(snapshot_OUT "${CMAKE_CURRENT_BINARY_DIR}/snapshot-report/${name}")
  endif()
  set(command "${glint}" snapshot "${suite}" --out "${snapshot_OUT}")
  if(snapshot_JOBS)
    list(APPEND command --jobs ${snapshot_JOBS})
  endif()
  if(snapshot_SHARD)
    list(APPEND command --shard ${snapshot_SHARD})
  endif()
  list(APPEND command ${snapshot_ARGS})

  add_test(NAME ${name} COMMAND ${command})
  # OSMesa needs no display; exit code 1 (a case failed or errored) and 2 (no run) both fail.
  set_tests_properties(${name} PROPERTIES ENVIRONMENT "DISPLAY=" LABELS "snapshot")
endfunction()
