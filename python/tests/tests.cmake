# The module's tests (CTest label `python`; scripts/test.sh runs them with the rest and fails when
# none is registered): python/tests/test_*.py with Debian's python3, the module from the build
# tree's python/ and the CLI beside it for the byte-for-byte comparisons.
file(GLOB _fcvt_python_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/test_*.py)
foreach(_test ${_fcvt_python_tests})
  get_filename_component(_name ${_test} NAME_WE)
  add_test(NAME python_${_name} COMMAND ${Python3_EXECUTABLE} ${_test})
  set_tests_properties(python_${_name} PROPERTIES LABELS python TIMEOUT 900
    ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python;FCVT_CLI=$<TARGET_FILE:fcvt>;FCVT_RESOURCES=${PROJECT_SOURCE_DIR}/resources;FCVT_BUILD_DIR=${CMAKE_BINARY_DIR}")
endforeach()
# The python3-fcvt package, unpacked and imported from its dist-packages path.
add_test(NAME python_package_installs
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/package_installs.sh ${CMAKE_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR}/package_work)
set_tests_properties(python_package_installs PROPERTIES LABELS "python;package" TIMEOUT 600)
