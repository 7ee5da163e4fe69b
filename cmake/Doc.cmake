# The `doc` target: the public API reference (HTML in <build>/doc/html) built by Doxygen from
# include/graspsim, failing on any warning (cmake/Doxyfile.in). With Doxygen present (Debian's
# doxygen, installed by `.ci/install --ci`), ctest also builds it (label doc), so CI checks it.
find_package(Doxygen QUIET)
if(NOT DOXYGEN_FOUND)
  return()
endif()
set(GRASPSIM_DOC_DIR ${PROJECT_BINARY_DIR}/doc)
configure_file(${PROJECT_SOURCE_DIR}/cmake/Doxyfile.in ${GRASPSIM_DOC_DIR}/Doxyfile @ONLY)
add_custom_target(doc
  COMMAND ${CMAKE_COMMAND} -E make_directory ${GRASPSIM_DOC_DIR}
  COMMAND ${DOXYGEN_EXECUTABLE} ${GRASPSIM_DOC_DIR}/Doxyfile
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMENT "Building the API reference in ${GRASPSIM_DOC_DIR}/html (Doxygen; any warning fails)"
  VERBATIM)
if(GRASPSIM_BUILD_TESTS)
  add_test(NAME doc_builds_without_warnings COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target doc)
  set_tests_properties(doc_builds_without_warnings PROPERTIES LABELS doc)
endif()
