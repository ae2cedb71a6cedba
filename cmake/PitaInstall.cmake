# Installing pita (docs/guide/install.md "Install"): cmake --install build --prefix P writes
#   P/bin/pita
#   P/libexec/pita/pita-serve           the server of pita serve
#   P/include/pita/<layer>/*.hpp        the headers of core, scene, motion, analysis, render
#   P/lib/libpita_<layer>.a             the libraries of those layers
#   P/lib/cmake/pita/pitaConfig.cmake   with pitaConfigVersion.cmake and the exported
#                                       targets pita::core and pita::render
#   P/lib/pkgconfig/pita.pc             pita::core for pkg-config
#   P/share/man/man1/pita.1             the man page, generated from the CLI at build time
#   P/share/bash-completion/completions/pita, P/share/zsh/vendor-completions/_pita
#   P/share/doc/pita/                   README.md, CHANGELOG.md, docs/
#   P/share/pita/scenes/                the scenes of the papers' figures (scenes/, with
#                                       their images), which pita.scenes_dir() and
#                                       pita.example(NAME) find from any folder
# and cpack -G DEB packs the same into pita_<version>_<arch>.deb (prefix /usr).
# With PITA_PYTHON, cpack makes a second package, python3-pita: the Python
# module (component python, src/python/CMakeLists.txt); everything else is
# the component pita.
# Included by the top CMakeLists.txt after src/.
set(CMAKE_INSTALL_DEFAULT_COMPONENT_NAME pita)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PITA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/pita)

install(TARGETS pita RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The server of `pita serve` (src/cli/serve.hpp), which pita finds at ../libexec/pita/.
if(TARGET pita-serve)
  install(TARGETS pita-serve RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/pita)
endif()

# The libraries a program may use: core (math, Eigen only) in one export set,
# render and the layers it stands on in another, so that a consumer of
# pita::core needs nothing but Eigen. animate, golden, sweep and cli stay
# inside the pita binary.
foreach(layer core scene motion analysis render)
  set_target_properties(pita_${layer} PROPERTIES EXPORT_NAME ${layer})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${layer} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/pita
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(TARGETS pita_core EXPORT pitaCoreTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# pita_io (how scene reads its files) is linked by pita_scene, privately: its
# archive goes with render's, its headers do not.
set_target_properties(pita_io PROPERTIES EXPORT_NAME io)
install(TARGETS pita_io pita_scene pita_motion pita_analysis pita_render EXPORT pitaRenderTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT pitaCoreTargets NAMESPACE pita:: DESTINATION ${PITA_INSTALL_CMAKEDIR})
install(EXPORT pitaRenderTargets NAMESPACE pita:: DESTINATION ${PITA_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/pitaConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/pitaConfig.cmake
                              INSTALL_DESTINATION ${PITA_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the API, so 0.2 accepts 0.2.y only.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/pitaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/pitaConfig.cmake ${CMAKE_BINARY_DIR}/pitaConfigVersion.cmake
        DESTINATION ${PITA_INSTALL_CMAKEDIR})

# pita.pc finds its prefix from its own place (${pcfiledir}), so the same file
# serves cmake --install --prefix P and the .deb's /usr.
file(RELATIVE_PATH PITA_PC_PREFIX_FROM_PCDIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" PITA_PC_PREFIX_FROM_PCDIR "${PITA_PC_PREFIX_FROM_PCDIR}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/pita.pc.in ${CMAKE_BINARY_DIR}/pita.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/pita.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# Written when pita is linked (src/CMakeLists.txt, cmake/PitaGenerate.cmake).
install(FILES ${CMAKE_BINARY_DIR}/pita.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${CMAKE_BINARY_DIR}/completions/pita DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES ${CMAKE_BINARY_DIR}/completions/_pita DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The guide, the reference and the explanation the README links to (the
# gallery's images are the goldens, which stay in the repository).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
# The scenes, so that a user reaches them from a folder of their own
# (src/python/examples.cpp bakes in the path from the module's folder).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/pita/scenes)

# The Debian package: cpack -G DEB in the build folder. Depends comes from
# dpkg-shlibdeps (Debian dpkg-dev, which build-essential brings) on the
# binary, plus the fonts the figures are drawn with; the development packages
# a consumer of the libraries needs are suggested (docs/guide/install.md "Install").
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pita)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "planar interpolation of three arrows and steady affine morphs")
set(CPACK_PACKAGE_DESCRIPTION
    "pita evaluates the planar interpolating three-arrow motions (PITAs P1-P10) and the steady affine morphs (SAM) of Rossignac and Vinacua, draws their figures (SVG, PNG, PDF) and checks them against goldens. The package also holds the C++ libraries pita::core (Eigen only) and pita::render, with their CMake and pkg-config files.")
set(CPACK_PACKAGE_CONTACT "pita maintainers <pita@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# pango is loaded at run time with dlopen (src/render/pango_library.hpp), so
# dpkg-shlibdeps cannot see it: its package is named here.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, libpangocairo-1.0-0")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, libcairo2-dev, libpango1.0-dev, libfmt-dev, nlohmann-json3-dev, pkg-config")
if(PITA_PYTHON)
  set(CPACK_DEB_COMPONENT_INSTALL ON)
  set(CPACK_COMPONENTS_ALL pita python)
  set(CPACK_DEBIAN_PITA_PACKAGE_NAME pita)
  set(CPACK_DEBIAN_PITA_FILE_NAME DEB-DEFAULT)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-pita)
  set(CPACK_DEBIAN_PYTHON_FILE_NAME DEB-DEFAULT)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION
      "Python module pita: the PITAs, steady morphs, SAM and EAR of pita from Python, vectorised over NumPy.")
  set(CPACK_DEBIAN_PYTHON_DESCRIPTION
      "Python module of pita: the interpolating motions of Rossignac and Vinacua\n The PITAs, the steady morph of arrows, the Steady Affine Morphs and the real powers of affinities (EAR), and the figures of pita's scene files, from Python and Jupyter: the same C++ as the pita command line, vectorised over NumPy arrays.")
  # The module is built for Debian's python3 (3.11 on Debian 12) and returns NumPy arrays.
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= ${PITA_PYTHON_VERSION}), python3 (<< ${PITA_PYTHON_NEXT_VERSION}), python3-numpy, fonts-dejavu-core, libpangocairo-1.0-0")
  # pita holds the scenes pita.example() finds (/usr/share/pita/scenes).
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "pita (= ${PROJECT_VERSION})")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-matplotlib, jupyter-nbconvert")
endif()
include(CPack)
