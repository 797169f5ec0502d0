# cmake -DBUILD=<conformesh build> -DPYTHON=<interpreter> -DPACKAGE_DIR=<CONFORMESH_PYTHON_INSTALL_DIR, relative>
#       -DVERSION=<project version> -P run_installed_package.cmake
# The Python package as a user gets it: `cmake --install --component python` into the scratch prefix
# BUILD/install-python-test (never the default prefix), then the interpreter run from another directory with
# PYTHONPATH set to the installed folder alone: the import must come from there, report the version and remesh.
set(prefix ${BUILD}/install-python-test)
set(elsewhere ${prefix}/elsewhere)
set(site ${prefix}/${PACKAGE_DIR})
file(REMOVE_RECURSE ${prefix})
file(MAKE_DIRECTORY ${elsewhere})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix} --component python
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "installed package: cmake --install failed with status ${status}:\n${out}\n${err}")
endif()
foreach(f __init__.py __init__.pyi _conformesh.pyi metrics.py metrics.pyi py.typed)
  if(NOT EXISTS ${site}/conformesh/${f})
    message(FATAL_ERROR "installed package: ${site}/conformesh/${f} was not installed")
  endif()
endforeach()
set(check [=[
import math, os, sys
import conformesh
site = os.path.realpath(sys.argv[1])
assert os.path.realpath(conformesh.__file__).startswith(site + os.sep), (conformesh.__file__, site)
assert conformesh.__version__ == sys.argv[2], (conformesh.__version__, sys.argv[2])
r = conformesh.remesh(conformesh.metrics.family("sphere"), 0.3)
t = r.triangulation
# Closed genus 0: Gauss-Bonnet sum of angle deficits = 4 pi to round-off; the area within 5% of 4 pi at eps = 0.3.
assert abs(t.angle_deficits().sum() - 4 * math.pi) < 1e-9, t.angle_deficits().sum()
assert abs(t.total_area / (4 * math.pi) - 1) < 0.05, t.total_area
print("conformesh", conformesh.__version__, "from", conformesh.__file__, "remeshed the sphere:", t.num_vertices,
      "vertices, area", t.total_area)
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONHOME PYTHONPATH=${site}
                        ${PYTHON} -c "${check}" ${site} ${VERSION}
                WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "installed package: the import check failed with status ${status}:\n${out}\n${err}")
endif()
message(STATUS "installed package: ${out}")
