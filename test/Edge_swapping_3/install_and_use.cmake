# SPDX-License-Identifier: GPL-3.0-or-later
# The install test: installs this build into a fresh prefix, then configures,
# builds and runs a user's project (external_project/) that finds the package
# with find_package(Edge_swapping_3), and the laboratory (laboratory/), which
# finds it the same way: its example is built and run. Arguments: -DBINARY_DIR
# -DWORK_DIR -DPROJECT_DIR -DLABORATORY_DIR -DBUILD_TYPE.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGV}")
    message(FATAL_ERROR "failed (${result}): ${command}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${PROJECT_DIR} -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/uses_edge_swapping_3)
run(${CMAKE_COMMAND} -S ${LABORATORY_DIR} -B ${WORK_DIR}/laboratory -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DBUILD_TESTING=OFF
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/laboratory --target conjecture_laboratory)
run(${WORK_DIR}/laboratory/bin/conjecture_laboratory)
