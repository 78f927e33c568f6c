# The Debian package: `cpack -G DEB` in the build folder (scripts/build-deb.sh does it and
# runs lintian). It packages what cmake/Install.cmake installs, under /usr. Dependencies
# on shared libraries are computed by dpkg-shlibdeps; the ones zeroset opens at run time
# are listed by hand: Mesa's drivers (llvmpipe when there is no GPU) for EGL and OSMesa
# rendering, and libGL for the viewer's window (GLFW and Dear ImGui load it).
set(ZS_DEB_MAINTAINER "zeroset maintainers <maintainers@users.noreply.h-seed-cd0d73c6.example>"
    CACHE STRING "Maintainer field of the .deb")

set(CPACK_PACKAGE_NAME zeroset)
set(CPACK_PACKAGE_VENDOR "the zeroset authors")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "ray tracer for implicit surfaces F(x, y, z) = 0")
set(CPACK_PACKAGE_CONTACT ${ZS_DEB_MAINTAINER})
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/packages)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # zeroset_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER ${ZS_DEB_MAINTAINER})
set(CPACK_DEBIAN_PACKAGE_SECTION math)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1, libgl1-mesa-dri, fonts-dejavu-core, fonts-dejavu-extra")
# Stripped as dh_strip strips, and the lintian overrides (cmake/DebStaging.cmake).
set(CPACK_PRE_BUILD_SCRIPTS ${PROJECT_SOURCE_DIR}/cmake/DebStaging.cmake)
# CPack hands that script the CPACK_* variables only.
set(CPACK_ZS_LINTIAN_OVERRIDES ${PROJECT_SOURCE_DIR}/packaging/lintian-overrides)
# Full RELRO (-z now: the global offset table read-only after start-up), as Debian's
# hardening flags ask of a packaged program.
target_link_options(zeroset PRIVATE LINKER:-z,relro LINKER:-z,now)
# surf's and SURFER's names, through the alternatives system (packaging/postinst).
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/packaging/postinst
                                       ${PROJECT_SOURCE_DIR}/packaging/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
# The long description; CPack puts the summary above it and formats it for the control file.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
"zeroset draws the surface where a formula in x, y and z is zero: type a
formula at its prompt or on the command line, or open a .surf scene file,
and turn, light and tune the surface in an interactive viewer, or render it
to a PNG without a window.

Interval arithmetic on an octree finds where the surface can be; a fragment
shader finds the roots along each ray, exactly for polynomials. Without a
GPU it renders on the CPU through Mesa's llvmpipe.

The package includes a gallery of classic algebraic surfaces (Barth, Clebsch,
Kummer, Togliatti, the Cayley cubic, ...), the man page, shell completion, a
desktop entry, and previews of .surf files in file managers.")

include(CPack)
