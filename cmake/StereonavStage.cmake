# One library per stage of the data path, so a stage builds and tests on its own and its
# dependencies on the other stages are written down. Each is exported as stereonav::<name>;
# stereonav::stereonav links them all.
set(STEREONAV_STAGES "" CACHE INTERNAL "")

function(stereonav_add_stage name)
  cmake_parse_arguments(ARG "" "" "SOURCES;HEADERS;DEPENDS" ${ARGN})
  set(target stereonav_${name})
  add_library(${target} ${ARG_SOURCES} ${ARG_HEADERS})
  add_library(stereonav::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME stereonav_${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/lib>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/stereonav>)
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS} PRIVATE $<BUILD_INTERFACE:stereonav_build_flags>)
  install(TARGETS ${target} EXPORT stereonavTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${ARG_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stereonav/${name})
  set(STEREONAV_STAGES ${STEREONAV_STAGES} ${target} CACHE INTERNAL "")
endfunction()
