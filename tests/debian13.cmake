# The Debian 13 (trixie) package, built and tested inside a Debian 13 root (label: debian13).
# debian13_package runs scripts/package-debian13.sh, which makes the root with debootstrap in
# the build directory (as root; about 2 minutes), installs MeshLab 2022.02 and the build
# dependencies in it (about 4), and builds the core, the plugin and the .deb there; the other
# tests then install that .deb with apt-get, check its symbols, run the three filters through
# MeshLab 2022.02's own plugin manager (fcvt-meshlab-host, tests/debian13/meshlab_host.cpp) with
# the same scripts and checks as the meshlabserver tests, and start the GUI under Xvfb. Each
# is skipped (status 77) when not run as root or when debootstrap fails. Nothing is cached
# outside the build directory; the root is made afresh each run (FCVT_DEBIAN13_FRESH=0 in the
# environment reuses a complete one, for development).
option(FCVT_TEST_DEBIAN13 "Test the Debian 13 package in a Debian 13 root (needs root and the archive)" ON)
if(NOT FCVT_TEST_DEBIAN13)
  return()
endif()
set(_d13 "${CMAKE_CURRENT_SOURCE_DIR}/debian13")
set(_d13_args "${PROJECT_BINARY_DIR}" "${PROJECT_SOURCE_DIR}")

add_test(NAME debian13_package COMMAND bash "${_d13}/package.sh" ${_d13_args})
set_tests_properties(debian13_package PROPERTIES LABELS "debian13;package" TIMEOUT 2700
  SKIP_RETURN_CODE 77 FIXTURES_SETUP debian13_built RESOURCE_LOCK debian13_root)
add_test(NAME debian13_deb_installs COMMAND bash "${_d13}/deb_installs.sh" ${_d13_args})
set_tests_properties(debian13_deb_installs PROPERTIES LABELS "debian13;package" TIMEOUT 600
  SKIP_RETURN_CODE 77 FIXTURES_REQUIRED debian13_built FIXTURES_SETUP debian13_installed
  RESOURCE_LOCK debian13_root)
add_test(NAME debian13_plugin_symbols COMMAND bash "${_d13}/symbols.sh" ${_d13_args})
add_test(NAME debian13_gui COMMAND bash "${_d13}/gui.sh" ${_d13_args} "${CMAKE_CURRENT_BINARY_DIR}/debian13/gui")
add_test(NAME debian13_gui_dialog COMMAND bash "${_d13}/gui_dialog.sh" ${_d13_args} "${CMAKE_CURRENT_BINARY_DIR}/debian13/gui_dialog")
set(_d13_tests debian13_plugin_symbols debian13_gui debian13_gui_dialog)

# The meshlabserver tests of tests/meshlab/, against MeshLab 2022.02 (tests/meshlab/common.sh,
# FCVT_MESHLAB_HOST). compare_isotropic is left out: it drives MeshLab's built-in filters, and
# MeshLab 2022.02 has no "Change the current layer" filter.
set(_d13_cli "")
if(TARGET fcvt)
  set(_d13_cli "$<TARGET_FILE:fcvt>")
endif()
foreach(_t plugin_loads remesh_torus invalid_parameter field_torus missing_rosy field_then_remesh
           colour_transfer quality_report invalid_new_parameters filter_equals_cli log_order)
  set(_extra "")
  if(_t STREQUAL "remesh_torus" OR _t STREQUAL "filter_equals_cli" OR _t STREQUAL "log_order")
    set(_extra ${_d13_cli})
  endif()
  add_test(NAME debian13_meshlab_${_t}
    COMMAND bash "${_d13}/meshlab_test.sh" ${_d13_args} "${CMAKE_CURRENT_SOURCE_DIR}/meshlab/${_t}.sh"
            "${CMAKE_CURRENT_BINARY_DIR}/debian13/${_t}" ${_extra})
  list(APPEND _d13_tests debian13_meshlab_${_t})
endforeach()
set_tests_properties(${_d13_tests} PROPERTIES LABELS debian13 TIMEOUT 900 SKIP_RETURN_CODE 77
  FIXTURES_REQUIRED "debian13_built;debian13_installed")
