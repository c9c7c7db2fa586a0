# The 3D viewer page (viewer/, issue 21), embedded in the library for io::write_html:
#   1. `npm ci` installs the pinned three.js (viewer/package-lock.json) into <build>/viewer/
#      node_modules, once per lock-file change; --prefer-offline takes npm's cache (~/.npm) when
#      it holds the package, so rebuilds work offline after the first install;
#   2. cmake/inline_viewer.cmake inlines three.js, its OrbitControls and viewer/viewer.js into
#      viewer/template.html and writes <build>/generated/pendepth/viewer_page.hpp.
# PENDEPTH_HTML_VIEWER=OFF builds without npm; write_html then throws InvalidInput.
option(PENDEPTH_HTML_VIEWER "Embed the 3D HTML viewer (needs npm at build time)" ON)
if(NOT PENDEPTH_HTML_VIEWER)
  return()
endif()
find_program(PENDEPTH_NPM npm)
if(NOT PENDEPTH_NPM)
  message(FATAL_ERROR "pendepth: the 3D HTML viewer needs npm at build time (scripts/setup.sh installs "
                      "it: apt-get install npm), or configure with -DPENDEPTH_HTML_VIEWER=OFF")
endif()
set(PENDEPTH_VIEWER_BUILD ${PROJECT_BINARY_DIR}/viewer)
set(PENDEPTH_VIEWER_HEADER ${PROJECT_BINARY_DIR}/generated/pendepth/viewer_page.hpp)
add_custom_command(
  OUTPUT ${PENDEPTH_VIEWER_BUILD}/npm-ci.stamp
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PENDEPTH_VIEWER_BUILD}
  COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/viewer/package.json
          ${PROJECT_SOURCE_DIR}/viewer/package-lock.json ${PENDEPTH_VIEWER_BUILD}
  COMMAND ${CMAKE_COMMAND} -E chdir ${PENDEPTH_VIEWER_BUILD}
          ${PENDEPTH_NPM} ci --prefer-offline --ignore-scripts --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${PENDEPTH_VIEWER_BUILD}/npm-ci.stamp
  DEPENDS ${PROJECT_SOURCE_DIR}/viewer/package.json ${PROJECT_SOURCE_DIR}/viewer/package-lock.json
  COMMENT "npm ci: three.js for the 3D viewer (viewer/package-lock.json)"
  VERBATIM)
add_custom_command(
  OUTPUT ${PENDEPTH_VIEWER_HEADER}
  COMMAND ${CMAKE_COMMAND} -DTEMPLATE=${PROJECT_SOURCE_DIR}/viewer/template.html
          -DVIEWER_JS=${PROJECT_SOURCE_DIR}/viewer/viewer.js -DNODE_MODULES=${PENDEPTH_VIEWER_BUILD}/node_modules
          -DOUT=${PENDEPTH_VIEWER_HEADER} -P ${PROJECT_SOURCE_DIR}/cmake/inline_viewer.cmake
  DEPENDS ${PENDEPTH_VIEWER_BUILD}/npm-ci.stamp ${PROJECT_SOURCE_DIR}/viewer/template.html
          ${PROJECT_SOURCE_DIR}/viewer/viewer.js ${PROJECT_SOURCE_DIR}/cmake/inline_viewer.cmake
  COMMENT "Inlining three.js and viewer/viewer.js into the 3D viewer page"
  VERBATIM)
