# The python3-fcvt Debian package: `cmake --build BUILD --target python3-fcvt-deb` (or `cpack
# --config BUILD/python/CPackConfig-python3-fcvt.cmake`) writes
# BUILD/python/package/python3-fcvt_<version>_amd64.deb with the module in
# /usr/lib/python3/dist-packages and its copyright file. A package of its own beside the plugin's
# (cmake/packaging.cmake): the plugin's users need no Python, the module's no MeshLab.
execute_process(COMMAND ${Python3_EXECUTABLE} -c "import sys; print(f'{sys.version_info[0]}.{sys.version_info[1]}')"
                OUTPUT_VARIABLE _fcvt_py_version OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REGEX MATCH "^([0-9]+)\\.([0-9]+)$" _fcvt_py_match "${_fcvt_py_version}")
math(EXPR _fcvt_py_next "${CMAKE_MATCH_2} + 1")
set(FCVT_PYTHON_DEB_DEPENDS
    "python3 (>= ${_fcvt_py_version}), python3 (<< ${CMAKE_MATCH_1}.${_fcvt_py_next}), python3-numpy, libgomp1, libc6, libstdc++6")
install(FILES "${PROJECT_SOURCE_DIR}/cmake/debian-copyright" DESTINATION share/doc/python3-fcvt RENAME copyright
        PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ COMPONENT python)
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/CPackConfig-python3-fcvt.cmake.in
               ${CMAKE_CURRENT_BINARY_DIR}/CPackConfig-python3-fcvt.cmake @ONLY)
add_custom_target(python3-fcvt-deb
  COMMAND ${CMAKE_CPACK_COMMAND} --config ${CMAKE_CURRENT_BINARY_DIR}/CPackConfig-python3-fcvt.cmake
          -B ${CMAKE_CURRENT_BINARY_DIR}/package
  DEPENDS fcvt_python
  COMMENT "python3-fcvt Debian package"
  VERBATIM)
