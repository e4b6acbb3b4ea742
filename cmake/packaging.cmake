# Debian package of the MeshLab plugin: `cpack` in the build directory writes
# meshlab-plugin-fcvt_<version>_amd64.deb, which installs libfilter_fcvt.so into Debian's MeshLab
# plugin directory (apt-get install ./meshlab-plugin-fcvt_*.deb), and its copyright file.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME meshlab-plugin-fcvt)
# The plugin is built against one MeshLab's headers and ABI: it needs exactly that MeshLab
# release (FCVT_MESHLAB_VERSION, from its source tree's ML_VERSION). The Debian 12 package
# (2020.09) keeps the plain version; the Debian 13 one (2022.02) is <version>+deb13 and the
# forky/sid one (2025.07) <version>+deb14, so the files and versions never mix. ">= X~" because
# Debian's version of 2025.07 is 2025.07~dfsg-4, which sorts before 2025.07.
string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _fcvt_ml_match "${FCVT_MESHLAB_VERSION}")
set(_fcvt_ml_year ${CMAKE_MATCH_1})
math(EXPR _fcvt_ml_next_month "${CMAKE_MATCH_2} + 1")
if(_fcvt_ml_next_month LESS 10)
  set(_fcvt_ml_next_month "0${_fcvt_ml_next_month}")
endif()
set(_fcvt_ml_range "meshlab (>= ${FCVT_MESHLAB_VERSION}~), meshlab (<< ${_fcvt_ml_year}.${_fcvt_ml_next_month})")
if(FCVT_MESHLAB_VERSION VERSION_LESS 2022)
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
elseif(FCVT_MESHLAB_VERSION VERSION_LESS 2023)
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION}+deb13)
else()
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION}+deb14)
endif()
set(CPACK_PACKAGE_CONTACT "FCVT developers <fcvt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Field-aligned CVT isotropic remeshing filter for MeshLab")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Debian 13 and later name the Qt 5 libraries libqt5*5t64.
if(FCVT_MESHLAB_API_USED STREQUAL "2022")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "${_fcvt_ml_range}, libgomp1, libqt5core5t64, libqt5gui5t64, libqt5widgets5t64, libqt5opengl5t64, libqt5xml5t64")
else()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "${_fcvt_ml_range}, libgomp1, libqt5core5a, libqt5gui5, libqt5widgets5, libqt5opengl5, libqt5xml5")
endif()
# Debian policy 12.5: every package ships its copyright file, uncompressed, in its doc directory
# (machine-readable, DEP-5; the project is GPL-3+, the LICENSE file at the top).
install(FILES "${CMAKE_CURRENT_LIST_DIR}/debian-copyright" DESTINATION "share/doc/${CPACK_PACKAGE_NAME}"
        RENAME copyright PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ COMPONENT meshlab_plugin)
# Only the plugin component (the plugin and its copyright file) goes into the package.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};meshlab_plugin;/")
include(CPack)
