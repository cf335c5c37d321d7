# Installs tessref from BINARY_DIR into WORK_DIR/prefix, then builds and runs the consumer, and
# checks that both the consumer and the installed `tessref` write images through the installed
# image I/O module (not the build tree's), with the same bytes as the build tree's `tessref`.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()
set(prefix ${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix})
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
     -DCMAKE_BUILD_TYPE=Release)
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)

# Neither may fall back on an environment override.
unset(ENV{TESSREF_IMAGE_IO_MODULE})
step(${WORK_DIR}/build/consumer ${WORK_DIR}/consumer.png)
if(NOT step_output MATCHES "image I/O module: ${prefix}/")
  message(FATAL_ERROR "the consumer did not use the installed image I/O module:\n${step_output}")
endif()

set(args render --threads 1 --set image.width=64 --set image.height=64)
set(installed_tessref ${prefix}/bin/tessref)
step(${installed_tessref} ${args} -o ${WORK_DIR}/installed.png)
step(${BINARY_DIR}/cli/tessref ${args} -o ${WORK_DIR}/build_tree.png)
step(${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/installed.png ${WORK_DIR}/build_tree.png)
step(${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/consumer.png ${WORK_DIR}/build_tree.png)
# The capture importer's scripts are installed, and the installed `tessref import` runs them: a
# file that is no capture is refused by the importer (exit 2, its message).
if(NOT EXISTS ${prefix}/share/tessref/replay/tessref_import.py)
  message(FATAL_ERROR "the capture importer was not installed under ${prefix}/share/tessref/replay")
endif()
unset(ENV{TESSREF_REPLAY_DIR})
execute_process(COMMAND ${installed_tessref} import ${WORK_DIR}/installed.png --out ${WORK_DIR}/imported
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 2 OR NOT err MATCHES "is neither a RenderDoc capture")
  message(FATAL_ERROR "the installed tessref import did not run the importer (exit ${rc}):\n${err}")
endif()
message(STATUS "consumer built and ran against the installed tessref")
