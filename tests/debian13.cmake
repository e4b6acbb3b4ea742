# The packages for newer Debians, each built and tested inside a root of its release:
#   debian13_* (label debian13): Debian 13 trixie, MeshLab 2022.02;
#   forky_*    (label forky):    Debian testing forky (made as sid is), MeshLab 2025.07.
# <tag>_package runs scripts/package-debian.sh RELEASE, which makes the root with debootstrap in
# the build directory (as root; about 2 minutes), installs the release's MeshLab and the build
# dependencies in it (about 4), and builds the core, the plugin and the .deb there; the other
# tests then install that .deb with apt-get, check its symbols, run the three filters through
# that MeshLab's own plugin manager (fcvt-meshlab-host, tests/debian13/meshlab_host.cpp; its
# version and precision checks included) with the same scripts and checks as the meshlabserver
# tests, start the GUI under Xvfb and open the remeshing dialog. Each is skipped (status 77) when
# not run as root or when debootstrap fails. Nothing is cached outside the build directory; the
# roots are made afresh each run (FCVT_DEBIAN13_FRESH=0 in the environment reuses complete ones,
# for development).
option(FCVT_TEST_DEBIAN13 "Test the Debian 13 package in a Debian 13 root (needs root and the archive)" ON)
option(FCVT_TEST_FORKY "Test the forky (MeshLab 2025.07) package in a forky root (needs root and the archive)" ON)
set(_d13 "${CMAKE_CURRENT_SOURCE_DIR}/debian13")
set(_d13_args "${PROJECT_BINARY_DIR}" "${PROJECT_SOURCE_DIR}")
set(_d13_cli "")
if(TARGET fcvt)
  set(_d13_cli "$<TARGET_FILE:fcvt>")
endif()

# fcvt_debian_release_tests(TAG RELEASE): the tests of one release, named TAG_*.
function(fcvt_debian_release_tests tag release)
  set(_env "FCVT_DEBIAN_RELEASE=${release}")
  set(_work "${CMAKE_CURRENT_BINARY_DIR}/${tag}")
  add_test(NAME ${tag}_package COMMAND bash "${_d13}/package.sh" ${_d13_args})
  set_tests_properties(${tag}_package PROPERTIES LABELS "${tag};package" TIMEOUT 2700
    SKIP_RETURN_CODE 77 FIXTURES_SETUP ${tag}_built RESOURCE_LOCK ${tag}_root ENVIRONMENT "${_env}")
  add_test(NAME ${tag}_deb_installs COMMAND bash "${_d13}/deb_installs.sh" ${_d13_args})
  set_tests_properties(${tag}_deb_installs PROPERTIES LABELS "${tag};package" TIMEOUT 600
    SKIP_RETURN_CODE 77 FIXTURES_REQUIRED ${tag}_built FIXTURES_SETUP ${tag}_installed
    RESOURCE_LOCK ${tag}_root ENVIRONMENT "${_env}")
  add_test(NAME ${tag}_plugin_symbols COMMAND bash "${_d13}/symbols.sh" ${_d13_args})
  add_test(NAME ${tag}_gui COMMAND bash "${_d13}/gui.sh" ${_d13_args} "${_work}/gui")
  add_test(NAME ${tag}_gui_dialog COMMAND bash "${_d13}/gui_dialog.sh" ${_d13_args} "${_work}/gui_dialog")
  set(_tests ${tag}_plugin_symbols ${tag}_gui ${tag}_gui_dialog)
  # The meshlabserver tests of tests/meshlab/, against the release's MeshLab (tests/meshlab/common.sh,
  # FCVT_MESHLAB_HOST). compare_isotropic is left out: it drives MeshLab's built-in filters, and
  # MeshLab 2022.02 and later have no "Change the current layer" filter.
  foreach(_t plugin_loads remesh_torus invalid_parameter field_torus missing_rosy field_then_remesh
             colour_transfer quality_report invalid_new_parameters filter_equals_cli log_order remesh_selected
             texture_transfer exact_count preset)
    # filter_equals_cli compares the plugin with this machine's CLI, bit for bit in effect: the
    # forky plugin is built by GCC 16 against glibc 2.43's libm, and the last digits of its
    # floating point differ, which the valence stage amplifies on small scans (V6 63.8 against
    # 64.2 % on many_small_holes). It runs for 2020.09 and 2022.02 (GCC 12 and 14: the same bits).
    # exact_count compares vertex counts with the CLI's on a thin part, preset the vertex and face
    # counts after the valence stage: as sensitive.
    if(tag STREQUAL "forky" AND (_t STREQUAL "filter_equals_cli" OR _t STREQUAL "exact_count" OR _t STREQUAL "preset"))
      continue()
    endif()
    set(_extra "")
    if(_t STREQUAL "remesh_torus" OR _t STREQUAL "filter_equals_cli" OR _t STREQUAL "log_order" OR _t STREQUAL "texture_transfer"
       OR _t STREQUAL "exact_count" OR _t STREQUAL "preset")
      set(_extra ${_d13_cli})
    endif()
    add_test(NAME ${tag}_meshlab_${_t}
      COMMAND bash "${_d13}/meshlab_test.sh" ${_d13_args} "${CMAKE_CURRENT_SOURCE_DIR}/meshlab/${_t}.sh"
              "${_work}/${_t}" ${_extra})
    list(APPEND _tests ${tag}_meshlab_${_t})
  endforeach()
  add_test(NAME ${tag}_meshlab_python_names
    COMMAND bash "${_d13}/meshlab_test.sh" ${_d13_args} "${_d13}/python_names.sh" "${_work}/python_names")
  list(APPEND _tests ${tag}_meshlab_python_names)
  set_tests_properties(${_tests} PROPERTIES LABELS ${tag} TIMEOUT 900 SKIP_RETURN_CODE 77
    FIXTURES_REQUIRED "${tag}_built;${tag}_installed" ENVIRONMENT "${_env}")
endfunction()

# forky_upstream_double_*: the double-precision plugin for MeshLab 2025.07's downloads and
# pymeshlab, built in the forky root with scripts/build-upstream-plugin.sh against the 2025.07
# source tree (its libmeshlab-common and io_base built double there; about 5 minutes), then
# loaded by that build's plugin manager (version and precision checks) through the test host and
# run with the meshlabserver tests' scripts.
function(fcvt_upstream_double_tests)
  set(_env "FCVT_DEBIAN_RELEASE=forky")
  set(_work "${CMAKE_CURRENT_BINARY_DIR}/forky_upstream_double")
  add_test(NAME forky_upstream_double_build COMMAND bash "${_d13}/upstream_build.sh" ${_d13_args})
  set_tests_properties(forky_upstream_double_build PROPERTIES LABELS "forky;package" TIMEOUT 1800
    SKIP_RETURN_CODE 77 FIXTURES_REQUIRED forky_built FIXTURES_SETUP forky_upstream_double
    RESOURCE_LOCK forky_root ENVIRONMENT "${_env}")
  set(_tests)
  foreach(_t meshlab/plugin_loads meshlab/remesh_torus meshlab/invalid_parameter meshlab/quality_report
             debian13/python_names)
    get_filename_component(_name ${_t} NAME)
    add_test(NAME forky_upstream_double_meshlab_${_name}
      COMMAND bash "${_d13}/meshlab_test.sh" ${_d13_args} "${CMAKE_CURRENT_SOURCE_DIR}/${_t}.sh"
              "${_work}/${_name}")
    list(APPEND _tests forky_upstream_double_meshlab_${_name})
  endforeach()
  set_tests_properties(${_tests} PROPERTIES LABELS forky TIMEOUT 900 SKIP_RETURN_CODE 77
    FIXTURES_REQUIRED "forky_built;forky_upstream_double" ENVIRONMENT "${_env};FCVT_UPSTREAM_DOUBLE=1")
endfunction()

if(FCVT_TEST_DEBIAN13)
  fcvt_debian_release_tests(debian13 trixie)
endif()
if(FCVT_TEST_FORKY)
  fcvt_debian_release_tests(forky forky)
  fcvt_upstream_double_tests()
endif()
