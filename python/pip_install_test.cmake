# cmake -DPYTHON=/usr/bin/python3 -DSOURCE_DIR=<repo> [-DWORK_DIR=<dir>] -P pip_install_test.cmake
# (CTest: python.pip_install). Runs the README's Python install commands as written, from a copy of the
# repository root (so that nothing is written into the checkout):
#   PYTHON -m venv --system-site-packages VENV
#   VENV/bin/python -m pip install --no-build-isolation ./python
#   VENV/bin/python -m pip wheel --no-build-isolation --no-deps -w dist ./python
# then imports boxcyl from VENV and runs the pytest suite against it, and installs the wheel into a
# fresh venv and queries it there.
# The copy must not lie under a path containing "build": setuptools silently skips absolute source
# paths containing that word instead of refusing them, so a test there would pass a setup.py that
# fails for users. Hence the default WORK_DIR in the temporary directory, not in the build tree.
if(NOT DEFINED WORK_DIR)
  set(tmp "$ENV{TMPDIR}")
  if(tmp STREQUAL "")
    set(tmp /tmp)
  endif()
  string(RANDOM LENGTH 8 suffix)
  set(WORK_DIR ${tmp}/boxcyl-pip-${suffix})
  set(remove_on_success ON)
endif()
if(WORK_DIR MATCHES "build")
  message(FATAL_ERROR "WORK_DIR ${WORK_DIR} contains \"build\", which would hide absolute source paths "
                      "from setuptools' check; choose another")
endif()
set(root ${WORK_DIR}/boxcyl)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${root})
message(STATUS "copy of the repository: ${root}")

# The repository root without version control, build trees and what an earlier pip run left behind.
file(GLOB entries LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/* ${SOURCE_DIR}/.*)
foreach(e ${entries})
  if(NOT e MATCHES "^(\\.|\\.\\.|\\.git|build.*|out|VENV.*|dist)$")
    file(COPY ${SOURCE_DIR}/${e} DESTINATION ${root}
         REGEX "/python/(build|dist|[^/]*\\.egg-info)$" EXCLUDE
         REGEX "/__pycache__$" EXCLUDE)
  endif()
endforeach()

unset(ENV{PYTHONPATH})
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
set(ENV{PIP_DISABLE_PIP_VERSION_CHECK} 1)  # no network access needed (or wanted) by a test

function(run what)
  list(JOIN ARGN " " command)
  message(STATUS "${what}: ${command}")
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${root} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}); the copy is kept in ${root}")
  endif()
endfunction()

# The boxcyl that `python` imports must be the one installed in `venv`, and must answer a query.
set(check [=[
import sys, boxcyl
venv = sys.argv[1]
assert boxcyl.__file__.startswith(venv + "/"), f"imported {boxcyl.__file__}, not the one in {venv}"
cyl = boxcyl.Cylinder(center=(3, 0, 0), axis=(0, 0, 5), radius=2, height=1)
assert boxcyl.intersects(boxcyl.AlignedBox(min=(-1, -1, -1), max=(1, 1, 1)), cyl) is True
assert boxcyl.intersects(boxcyl.AlignedBox(min=(-1, -1, -1), max=(0.5, 1, 1)), cyl) is False
from importlib.metadata import metadata
assert metadata("boxcyl")["License"] == "MIT", metadata("boxcyl")["License"]
print("boxcyl", boxcyl.__file__)
]=])

run("venv" ${PYTHON} -m venv --system-site-packages VENV)
run("pip install" VENV/bin/python -m pip install --no-build-isolation ./python)
run("import from VENV" VENV/bin/python -c "${check}" ${root}/VENV)
run("pytest against VENV" VENV/bin/python -m pytest -q -p no:cacheprovider python/tests)

run("pip wheel" VENV/bin/python -m pip wheel --no-build-isolation --no-deps -w dist ./python)
file(GLOB wheels ${root}/dist/boxcyl-*.whl)
list(LENGTH wheels n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "pip wheel made ${n} boxcyl wheels in ${root}/dist, not one")
endif()
run("venv for the wheel" ${PYTHON} -m venv --system-site-packages VENV-wheel)
run("pip install the wheel" VENV-wheel/bin/python -m pip install ${wheels})
run("import from VENV-wheel" VENV-wheel/bin/python -c "${check}" ${root}/VENV-wheel)

if(remove_on_success)
  file(REMOVE_RECURSE ${WORK_DIR})
endif()
