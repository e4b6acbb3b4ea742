# Debian package of the MeshLab plugin: `cpack` in the build directory writes
# meshlab-plugin-fcvt_<version>_amd64.deb, which installs libfilter_fcvt.so into Debian's MeshLab
# plugin directory (apt-get install ./meshlab-plugin-fcvt_*.deb).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME meshlab-plugin-fcvt)
# The Debian 12 package keeps the plain version; the Debian 13 one (MeshLab 2022.02 API) is
# <version>+deb13, so the two files and versions never mix.
if(FCVT_MESHLAB_API_USED STREQUAL "2022")
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION}+deb13)
else()
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
endif()
set(CPACK_PACKAGE_CONTACT "FCVT developers <fcvt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Field-aligned CVT isotropic remeshing filter for MeshLab")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# The plugin is built against one MeshLab's headers and ABI: it needs exactly that MeshLab
# (2020.09 on Debian 12; 2022.02 on Debian 13, where the Qt 5 core library is libqt5core5t64).
if(FCVT_MESHLAB_API_USED STREQUAL "2022")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "meshlab (>= 2022.02), meshlab (<< 2022.03), libgomp1, libqt5core5t64, libqt5gui5t64, libqt5widgets5t64, libqt5opengl5t64, libqt5xml5t64")
else()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "meshlab (>= 2020.09), meshlab (<< 2020.10), libgomp1, libqt5core5a, libqt5gui5, libqt5widgets5, libqt5opengl5, libqt5xml5")
endif()
# Only the plugin component goes into the package.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};meshlab_plugin;/")
include(CPack)
