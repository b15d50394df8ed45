# Installs the build tree into a scratch prefix, then configures, builds and runs the consumer
# project against it: what `find_package(stereonav)` gives a user. Run with -DBUILD_DIR,
# -DSOURCE_DIR, -DWORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                OUTPUT_QUIET RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} failed: ${result}")
endif()
foreach(step configure build run)
  if(step STREQUAL configure)
    set(command ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G Ninja
                -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
  elseif(step STREQUAL build)
    set(command ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
  else()
    set(command ${WORK_DIR}/build/consumer)
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  if(result)
    message(FATAL_ERROR "consumer ${step} failed (${result}):\n${output}")
  endif()
endforeach()
message(STATUS "${output}")
