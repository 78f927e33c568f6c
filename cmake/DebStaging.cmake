# CPACK_PRE_BUILD_SCRIPTS for the .deb: runs on CPack's staging tree after the install and
# before the package is made, for what only a Debian package wants (cmake/Package.cmake):
# the program stripped as dh_strip does (no .comment and .note sections either), and the
# lintian overrides, with their reasons, from packaging/lintian-overrides (installed as
# /usr/share/lintian/overrides/zeroset, in the .deb only).
set(root ${CPACK_TEMPORARY_DIRECTORY})
set(program ${root}/usr/bin/zeroset)
if(NOT EXISTS ${program})
  message(FATAL_ERROR "DebStaging: no ${program} in CPack's staging tree")
endif()
file(MAKE_DIRECTORY ${root}/usr/share/lintian/overrides)
find_program(ZS_STRIP NAMES strip REQUIRED)
execute_process(COMMAND ${ZS_STRIP} --remove-section=.comment --remove-section=.note
                        --strip-unneeded ${program}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "DebStaging: strip ${program} failed")
endif()
# file(COPY), not file(INSTALL): CPack's DESTDIR must not be put in front of ${root} again.
file(COPY_FILE ${CPACK_ZS_LINTIAN_OVERRIDES} ${root}/usr/share/lintian/overrides/zeroset)
