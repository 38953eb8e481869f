# `cpack -G DEB` in the build directory: a Debian package of what cmake/install.cmake installs,
# under /usr. Depends comes from the libraries the binary and the image module link
# (dpkg-shlibdeps, from dpkg-dev, which build-essential brings), so it follows the machine's
# Mesa, OpenImageIO and Embree; the tools some commands run are Recommends, as a command without
# them says which package it needs (`render --via dolphin`: dolphin-emu, xvfb; compiling an
# export for the Wii: the PowerPC cross gcc; the contact sheet's labels: DejaVu Sans).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ltrender)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "ltrender maintainers <ltrender@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Translucency on low-end pipelines: renders, error against a double reference, budgets")
set(CPACK_PACKAGE_DESCRIPTION
  "Renders the translucency approximation of Barre-Brisebois and Bouchard (GDC 2011) offscreen
through OSMesa by several paths (GLSL, ARB programs, GL 1.3 combiners, fp16, the Wii's GX), each
judged against a double-precision ground truth; checks shader budgets and regression renders
against goldens in CI (JUnit XML).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
  "dolphin-emu, xvfb, gcc-powerpc-linux-gnu, libc6-dev-powerpc-cross, fonts-dejavu-core")
include(CPack)
