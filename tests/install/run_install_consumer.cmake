# cmake -DBUILD=<conformesh build> -DSOURCE=<tests/install> -DMESH=<a mesh file> -P run_install_consumer.cmake
# Installs the build into BUILD/install-test, builds tests/install against it with find_package(conformesh), runs it.
set(prefix ${BUILD}/install-test)
set(consumer ${BUILD}/install-consumer)
file(REMOVE_RECURSE ${prefix} ${consumer})
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${SOURCE};-B;${consumer};-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release"
    "${CMAKE_COMMAND};--build;${consumer}"
    "${consumer}/consumer;${MESH}")
  execute_process(COMMAND ${step} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "install consumer: step `${step}` failed with status ${status}:\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "install consumer: ${out}")
