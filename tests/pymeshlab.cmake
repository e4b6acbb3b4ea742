# The plugin in pymeshlab, MeshLab 2025.07's Python scripting (label pymeshlab; issue 53): built on
# this machine for MeshLab 2025.07 double precision (scripts/build-upstream-plugin.sh --double,
# against the forky tests' MeshLab 2025.07 source tree), loaded with pymeshlab.load_plugin into
# the pymeshlab of ../shared/pymeshlab (2025.7.post1, double precision; FCVT_PYMESHLAB_DIR sets
# another) with /usr/bin/python3, and run there against the CLI. pymeshlab_plugin_build writes
# its status; without pymeshlab or a MeshLab 2025.07 source tree every test is skipped (77).
set(_pml_dir "${CMAKE_CURRENT_SOURCE_DIR}/pymeshlab")
set(_pml_work "${CMAKE_CURRENT_BINARY_DIR}/pymeshlab")
set(_pml_cli "")
if(TARGET fcvt)
  set(_pml_cli "$<TARGET_FILE:fcvt>")
endif()
add_test(NAME pymeshlab_plugin_build
  COMMAND bash "${_pml_dir}/build_plugin.sh" "${PROJECT_SOURCE_DIR}" "${PROJECT_BINARY_DIR}" "${_pml_work}")
# The first build compiles MeshLab's libmeshlab-common in double precision (10-20 minutes on two
# busy cores); later runs are incremental.
set_tests_properties(pymeshlab_plugin_build PROPERTIES LABELS pymeshlab TIMEOUT 3600 SKIP_RETURN_CODE 77
  FIXTURES_SETUP pymeshlab_plugin)
foreach(_t remesh_equals_cli quality_report field bad_parameter compare_isotropic)
  add_test(NAME pymeshlab_${_t}
    COMMAND bash "${_pml_dir}/run.sh" "${PROJECT_SOURCE_DIR}" "${_pml_work}" ${_t} ${_pml_cli})
  set_tests_properties(pymeshlab_${_t} PROPERTIES LABELS pymeshlab TIMEOUT 900 SKIP_RETURN_CODE 77
    FIXTURES_REQUIRED pymeshlab_plugin)
endforeach()
