# Debian package of the MeshLab plugin: `cpack` in the build directory writes
# meshlab-plugin-fcvt_<version>_amd64.deb, which installs libfilter_fcvt.so into Debian's MeshLab
# plugin directory (apt-get install ./meshlab-plugin-fcvt_*.deb).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME meshlab-plugin-fcvt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "FCVT developers <fcvt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Field-aligned CVT isotropic remeshing filter for MeshLab")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# The plugin is built against MeshLab 2020.09's headers and ABI: it needs exactly that MeshLab.
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "meshlab (>= 2020.09), meshlab (<< 2020.10), libgomp1, libqt5core5a, libqt5gui5, libqt5widgets5, libqt5opengl5, libqt5xml5")
# Only the plugin component goes into the package.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};meshlab_plugin;/")
include(CPack)
