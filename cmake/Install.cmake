# `cmake --install build [--prefix P]`: the zeroset program and everything it needs at run
# time or on a desktop, in the usual places under P (default /usr/local; the .deb uses /usr):
#   bin/zeroset                                     the program
#   share/zeroset/examples/                         the gallery (found as ../share/zeroset
#                                                   beside bin/, so the tree may be moved)
#   share/doc/zeroset/                              README, docs/, copyright, changelog
#   share/man/man1/zeroset.1.gz                     generated from --help (src/app/docgen)
#   share/bash-completion/completions/zeroset       generated likewise
#   share/zsh/vendor-completions/_zeroset           generated likewise (ZS_ZSH_COMPLETION_DIR)
#   share/applications/zeroset.desktop              opens .surf files with `zeroset view`
#   share/icons/hicolor/NxN/apps/zeroset.png        rendered by zeroset (data/icons)
#   share/mime/packages/zeroset.xml                 the .surf (and .jsurf) file types
#   share/thumbnailers/zeroset.thumbnailer          .surf previews by `zeroset render`
# The shader templates are embedded in the program; nothing is read from the source tree.
include(GNUInstallDirs)
set(ZS_ZSH_COMPLETION_DIR ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions CACHE STRING
    "Where the zsh completion is installed (Debian's zsh reads vendor-completions)")

install(TARGETS zeroset RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(zs_examples_dir ${CMAKE_INSTALL_DATADIR}/zeroset/examples)
install(DIRECTORY examples/ DESTINATION ${zs_examples_dir}
        PATTERN render-all.sh EXCLUDE)  # a maintainer script for the source tree

install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
# README.md links to examples/...: a link keeps those links working in the installed docs.
file(RELATIVE_PATH zs_examples_from_docs /${CMAKE_INSTALL_DOCDIR} /${zs_examples_dir})
install(CODE "
  set(link \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DOCDIR}/examples\")
  message(STATUS \"Installing: \${link} -> ${zs_examples_from_docs}\")
  file(CREATE_LINK ${zs_examples_from_docs} \${link} SYMBOLIC)")

# copyright: ours, then the Debian copyright files of the packages whose code is built into
# the program (statically linked), read from this system at configure time.
set(zs_copyright ${PROJECT_BINARY_DIR}/generated/docs/copyright)
file(READ ${PROJECT_SOURCE_DIR}/packaging/copyright zs_text)
foreach(pkg glslang-dev libimgui-dev)
  set(notice /usr/share/doc/${pkg}/copyright)
  if(EXISTS ${notice})
    file(READ ${notice} zs_notice)
    string(APPEND zs_text "\n\n---- ${pkg}: ${notice} ----\n\n${zs_notice}")
  else()
    message(WARNING "${notice} is missing: the installed copyright file will lack it")
  endif()
endforeach()
file(WRITE ${zs_copyright}.new "${zs_text}")
configure_file(${zs_copyright}.new ${zs_copyright} COPYONLY)  # touched only when it changes
# The changelog is Debian's format (the .deb is a native package); its first entry names
# the version, which must be this project's.
file(STRINGS ${PROJECT_SOURCE_DIR}/packaging/changelog zs_changelog_top LIMIT_COUNT 1)
if(NOT zs_changelog_top MATCHES "^zeroset \\(${PROJECT_VERSION}\\)")
  message(WARNING "packaging/changelog starts with '${zs_changelog_top}', not version "
                  "${PROJECT_VERSION}: add an entry for this version")
endif()
set(zs_changelog_gz ${PROJECT_BINARY_DIR}/generated/docs/changelog.gz)
add_custom_command(OUTPUT ${zs_changelog_gz}
  COMMAND ${CMAKE_COMMAND} -DIN=${PROJECT_SOURCE_DIR}/packaging/changelog -DOUT=${zs_changelog_gz}
          -P ${PROJECT_SOURCE_DIR}/cmake/Gzip.cmake
  DEPENDS ${PROJECT_SOURCE_DIR}/packaging/changelog ${PROJECT_SOURCE_DIR}/cmake/Gzip.cmake
  VERBATIM)
add_custom_target(zs_changelog ALL DEPENDS ${zs_changelog_gz})
install(FILES ${zs_copyright} ${zs_changelog_gz} DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(FILES ${ZS_GENERATED_DOCS}/zeroset.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${ZS_GENERATED_DOCS}/zeroset.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME zeroset)
install(FILES ${ZS_GENERATED_DOCS}/_zeroset DESTINATION ${ZS_ZSH_COMPLETION_DIR})

install(FILES data/zeroset.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(DIRECTORY data/icons/hicolor DESTINATION ${CMAKE_INSTALL_DATADIR}/icons)
install(FILES data/zeroset-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME zeroset.xml)
install(FILES data/zeroset.thumbnailer DESTINATION ${CMAKE_INSTALL_DATADIR}/thumbnailers)

# A plain `cmake --install` refreshes the desktop's caches for the prefix, as a package's
# triggers would, so .surf files are known at once; staged installs (DESTDIR, CPack) skip it.
install(CODE "
  if(\"\$ENV{DESTDIR}\" STREQUAL \"\")
    set(share \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}\")
    find_program(zs_update_mime update-mime-database)
    find_program(zs_update_desktop update-desktop-database)
    find_program(zs_update_icons gtk-update-icon-cache)
    if(zs_update_mime)
      execute_process(COMMAND \${zs_update_mime} \${share}/mime)
    endif()
    if(zs_update_desktop)
      execute_process(COMMAND \${zs_update_desktop} -q \${share}/applications)
    endif()
    if(zs_update_icons)
      execute_process(COMMAND \${zs_update_icons} -q -t -f \${share}/icons/hicolor)
    endif()
  endif()")
